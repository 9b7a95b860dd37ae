function expect_rel(actual, expected, rtol, what)
% Fails unless |actual - expected| <= rtol |expected| (element-wise; equal sizes); rtol 0 asks for equality.
  ok = isequal(size(actual), size(expected)) && all(abs(actual(:) - expected(:)) <= rtol * abs(expected(:)));
  if ~ok
    error('wrc_test:failed', 'FAILED: %s: got %s, expected %s (rtol %g)', what, mat2str(actual, 17), ...
          mat2str(expected, 17), rtol);
  end
end
