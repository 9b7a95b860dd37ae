function expect_true(condition, what)
% Fails the test (an error naming the check) unless condition is true.
  if ~(islogical(condition) || isnumeric(condition)) || isempty(condition) || ~all(condition(:))
    error('wrc_test:failed', 'FAILED: %s', what);
  end
end
