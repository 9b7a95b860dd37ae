function expect_error(f, id, pattern, what)
% Fails unless calling f() raises an error with identifier id whose message matches the regular expression pattern.
  try
    f();
  catch err
    if ~strcmp(err.identifier, id) || isempty(regexp(err.message, pattern, 'once'))
      error('wrc_test:failed', 'FAILED: %s: got error [%s] "%s", expected [%s] matching "%s"', what, ...
            err.identifier, err.message, id, pattern);
    end
    return;
  end
  error('wrc_test:failed', 'FAILED: %s: no error, expected [%s]', what, id);
end
