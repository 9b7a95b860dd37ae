% Bad input through the MEX interface: every case is a MATLAB error with an identifier and a message naming what is
% wrong (the engine's own message for an option, with the closest key for a misspelt one), never a crash of Octave
% (the test reaching its end shows that). Objects used after wrc.free are refused ('wrc:freed').
[ws, wheel, rail] = paper_wheelset();
pose = {'y', 0, 'z', -1e-5, 'roll', 0, 'yaw', 0};

% Misspelt keys: the engine's message, with the closest key.
expect_error(@() wrc.wheelset('wheel', wheel, 'rail', rail, 'gague', 1.435), 'wrc:error', ...
             'wrc_wheelset_new: unknown key ''gague'' \(did you mean ''gauge''', 'misspelt wheelset key');
expect_error(@() wrc.contact(ws, pose{:}, 'grdi', true), 'wrc:error', 'unknown key ''grdi'' \(did you mean ''grids''', ...
             'misspelt contact key');
expect_error(@() wrc.profile_load('profiles/s1002.lua', 'mirror_x', true), 'wrc:error', 'unknown option ''mirror_x''.*did you mean ''mirror_y''', ...
             'misspelt profile key');
expect_error(@() wrc.conicity(ws, 'yhat', 3e-3, 'methd', 'integral'), 'wrc:error', ...
             'unknown key ''methd''.*did you mean ''method''', ...
             'misspelt conicity key');

% Misspelt required arguments (read by the MEX layer, not the engine): the same suggestion, by the engine's rule; a
% name that is no typo of the missing one (V for yaw) gets none.
expect_error(@() wrc.equilibrium(ws, 'yy', 0, 'yaw', 0, 'Q', 200e3), 'wrc:missingArgument', ...
             '''y'' is missing \(did you mean ''y'' for ''yy''\?', 'misspelt required y');
expect_error(@() wrc.contact(ws, 'y', 0, 'z', -1e-5, 'rol', 0, 'yaw', 0), 'wrc:missingArgument', ...
             '''roll'' is missing \(did you mean ''roll'' for ''rol''\?', 'misspelt required roll');
expect_error(@() wrc.wheel(ws, 'Side', 'left', 'y', 0, 'yaw', 0, 'roll', 0, 'Fz', 1e5), 'wrc:missingArgument', ...
             'did you mean ''side'' for ''Side''\?', 'required side in another case');
expect_error(@() wrc.wheelset('wheel', wheel, 'rial', rail), 'wrc:missingArgument', ...
             'did you mean ''rail'' for ''rial''\?', 'misspelt profile of a wheelset');
expect_error(@() wrc.conicity('y', [-1 0 1] * 1e-3, 'd', [-1 0 1] * 1e-4), 'wrc:missingArgument', ...
             'did you mean ''dr'' for ''d''\?', 'misspelt Δr table');
expect_error(@() wrc.profile_points('kind', 'wheel', 'y', [0 1 2] * 1e-3, 'z', [0 0 0], 'nmae', 'w'), 'wrc:usage', ...
             'unknown key ''nmae'' \(did you mean ''name''\?', 'misspelt profile_points key');
try
  wrc.contact(ws, 'y', 0, 'z', -1e-5, 'roll', 0, 'V', 30);
  error('wrc_test:failed', 'FAILED: yaw missing: no error');
catch err
  expect_true(strcmp(err.identifier, 'wrc:missingArgument') && isempty(strfind(err.message, 'did you mean')), ...
              ['V is no misspelt yaw: ' err.message]);
end

% NaN and infinity: an argument of the C function, an option, a point, a Δr table.
expect_error(@() wrc.contact(ws, 'y', NaN, 'z', -1e-5, 'roll', 0, 'yaw', 0), 'wrc:invalidArgument', ...
             'y = NaN must be a finite number', 'NaN pose argument');
expect_error(@() wrc.wheel(ws, 'side', 'left', 'y', 0, 'yaw', 0, 'roll', 0, 'Fz', Inf), 'wrc:invalidArgument', ...
             'Fz = inf must be a finite number', 'infinite Fz');
expect_error(@() wrc.contact(ws, pose{:}, 'V', 30, 'creepage.xi', 1e-3, 'mu', NaN), 'wrc:error', ...
             '''mu'' must be finite, got NaN', 'NaN option');
expect_error(@() wrc.wheelset('wheel', wheel, 'rail', rail, 'radius', NaN), 'wrc:error', ...
             '''radius'' must be finite', 'NaN wheelset option');
expect_error(@() wrc.profile_points('kind', 'wheel', 'y', [0 NaN 2] * 1e-3, 'z', [0 0 0]), 'wrc:error', ...
             'point 2: coordinate is not a finite number', 'NaN profile point');
expect_error(@() wrc.geometry_table(ws, 'y', struct('from', -1e-3, 'to', 1e-3, 'step', NaN)), 'wrc:error', ...
             '''step'' must be finite', 'NaN in a nested struct option');

% The engine's messages in MATLAB's words: creepage is a struct (creepage.xi), and a position an ordinal, which reads
% the same from every front end: y(2) of MATLAB is the 2nd value (Python's y[1], Lua's y[2]).
expect_error(@() wrc.contact(ws, pose{:}, 'creepage', 1e-3, 'mu', 0.3), 'wrc:error', ...
             '''creepage'' must be a struct, got number', 'a number for a struct');
expect_error(@() wrc.geometry_table(ws, 'y', [-1e-3 NaN 1e-3]), 'wrc:error', ...
             'the 2nd value of ''y'' must be finite', 'NaN at y(2)');

% Files and values the engine refuses.
expect_error(@() wrc.profile_load('no/such/file.txt'), 'wrc:error', 'no/such/file.txt: no such file', 'missing file');
expect_error(@() wrc.contact(ws, 'y', 0, 'z', -5e-3, 'roll', 0, 'yaw', 0), 'wrc:error', ...
             'inter-penetrate .* more than max_penetration', 'a pose far too deep');
expect_error(@() wrc.rigid(ws, 'y', 3e-3, 'yaw', 0, 'roll', 'lose'), 'wrc:error', '''roll'' must be "free"', ...
             'a bad word');
expect_error(@() wrc.flange_measures(rail), 'wrc:error', 'is a rail profile, not a wheel', 'flange measures of a rail');
expect_error(@() wrc.contact(ws, pose{:}, 'y', 1e-3), 'wrc:error', '''y'' is an argument of wrc_contact, not an option', ...
             'a pose argument given twice');

% Wrong MATLAB types: refused before the engine sees them.
expect_error(@() wrc.profile_load(42), 'wrc:type', 'path must be a character row vector', 'a number as a path');
expect_error(@() wrc.contact(ws, 'y', 'abc', 'z', 0, 'roll', 0, 'yaw', 0), 'wrc:type', '''y'' must be real numbers', ...
             'a string as a pose');
expect_error(@() wrc.contact(ws, 'y', [1 2] * 1e-3, 'z', 0, 'roll', 0, 'yaw', 0), 'wrc:type', '''y'' must be one number', ...
             'a vector as a pose');
expect_error(@() wrc.contact(ws, 'y', 1i, 'z', 0, 'roll', 0, 'yaw', 0), 'wrc:type', 'must be real numbers', 'complex');
expect_error(@() wrc.contact(ws, pose{:}, 'mu', {0.3}), 'wrc:type', 'the value of ''mu'' must be real numbers', 'a cell');
expect_error(@() wrc.contact(ws, pose{:}, 'mu', [1 2; 3 4]), 'wrc:type', 'not a matrix', 'a matrix');
expect_error(@() wrc.contact(ws, pose{:}, 'mu', []), 'wrc:type', 'the value of ''mu'' is empty', 'an empty value');
expect_error(@() wrc.contact(ws, pose{:}, 'grids'), 'wrc:usage', '''grids'' has no value', 'an odd name/value list');
expect_error(@() wrc.contact(ws, pose{:}, 3, 4), 'wrc:type', 'an option name', 'a number as an option name');
expect_error(@() wrc.wheelset('wheel', wheel, 'rail', rail, 'strategy', 'coarse topology'), 'wrc:usage', ...
             'holds a blank', 'a word the option text cannot carry');
expect_error(@() wrc.contact(ws, struct('y', {0, 1})), 'wrc:type', 'must be 1x1', 'a struct array of options');
expect_error(@() wrc.contact(ws, pose{:}, 'grids', [true false]), 'wrc:type', 'one true or false', 'two logicals');
expect_error(@() wrc.profile_points('kind', 'wheel', 'y', [0 1 2] * 1e-3, 'z', [0 0]), 'wrc:usage', ...
             'y has 3 values, z 2', 'points of unequal length');
expect_error(@() wrc.conicity('y', [1 2] * 1e-3), 'wrc:missingArgument', '''y'' and ''dr''', 'a Δr table without dr');

% The C function's arguments are required (the C API has no default for them, and this interface writes none).
expect_error(@() wrc.equilibrium(ws, 'y', 3e-3, 'Q', 200e3), 'wrc:missingArgument', '''yaw'' is missing', ...
             'an argument left out');
expect_error(@() wrc.wheel(ws, 'y', 0, 'yaw', 0, 'roll', 0, 'Fz', 1e5), 'wrc:missingArgument', '''side'' is missing', ...
             'no side');
expect_error(@() wrc.wheel(ws, 'side', 'middle', 'y', 0, 'yaw', 0, 'roll', 0, 'Fz', 1e5), 'wrc:usage', ...
             'side = ''middle'' must be ''left'' or ''right''', 'a bad side');
expect_error(@() wrc.wheelset('wheel', wheel), 'wrc:missingArgument', 'give wheel and rail', 'a wheelset without rail');

% A misspelt key is named, also where it hides a key that is required: the engine's message names the closest key
% (another case before one edit: 'q' meant 'Q'); a C argument left out names the other names given.
expect_error(@() wrc.conicity(ws, 'yaht', 3e-3), 'wrc:error', 'unknown key ''yaht'' \(did you mean ''yhat''', ...
             'a misspelt required key');
expect_error(@() wrc.geometry_table(ws, 'y', struct('from', 0, 'too', 1e-3, 'step', 1e-3)), 'wrc:error', ...
             'unknown key ''too'' \(did you mean ''to''', 'a misspelt key of a range');
expect_error(@() wrc.rigid(ws, 'y', 0, 'yaw', 0, 'roll', 'free', 'hertz_lod', 1e5), 'wrc:error', ...
             'unknown key ''hertz_lod'' \(did you mean ''hertz_load''', 'a misspelt option');
expect_error(@() wrc.equilibrium(ws, 'y', 0, 'yaw', 0, 'q', 2e5), 'wrc:missingArgument', ...
             '''Q'' is missing .*the other names given: ''q''', 'a misspelt C argument');
expect_error(@() wrc.contact(ws, struct('y', 0, 'z', -1e-5, 'roll', 0, 'yaww', 0)), 'wrc:missingArgument', ...
             '''yaw'' is missing .*the other names given: ''yaww''', 'a misspelt C argument in a struct');
expect_error(@() wrc.conicity('y', [-2 -1 0 1 2] * 1e-3, 'drr', [-2 -1 0 1 2] * 1e-4, 'yhat', 1e-3), ...
             'wrc:missingArgument', ...
             '''dr''.*required \(did you mean ''dr'' for ''drr''\? the other names given: ''drr'', ''yhat''\)', ...
             'a misspelt dr');

% Numbers of the classes MATLAB users pass by accident: a uint64 (the class of the objects' ids) and a sparse matrix
% are named as what they are.
expect_error(@() wrc.contact(ws, 'y', uint64(0), 'z', -1e-5, 'roll', 0, 'yaw', 0), 'wrc:type', ...
             'must be real numbers \(got uint64, the class of wrc objects'' ids', 'a uint64 C argument');
expect_error(@() wrc.contact(ws, pose{:}, 'max_penetration', uint64(1)), 'wrc:type', ...
             'is a uint64 \(a wrc object, or a number', 'a uint64 option');
expect_error(@() wrc.contact(ws, 'y', sparse(0), 'z', -1e-5, 'roll', 0, 'yaw', 0), 'wrc:type', ...
             'got sparse double', 'a sparse C argument');

% Objects of the wrong kind, and things that are no wrc object.
expect_error(@() wrc.contact(wheel, pose{:}), 'wrc:type', 'is a profile, not a wheelset', 'a profile as a wheelset');
expect_error(@() wrc.wheelset('wheel', ws, 'rail', rail), 'wrc:type', 'is a wheelset, not a profile', ...
             'a wheelset as a profile');
expect_error(@() wrc.contact(3, pose{:}), 'wrc:type', 'must be a wrc object', 'a number as a wheelset');
expect_error(@() wrc.contact(ws, pose{:}, 'mu', wheel), 'wrc:type', 'must be real numbers \(got wrc.ProfileHandle\)', ...
             'a profile as an option value');
expect_error(@() wrc_mex('no_such_command'), 'wrc:usage', 'unknown command ''no_such_command''', 'an unknown command');

% A solve that does not converge: an error, or ok = false with the result when asked for.
expect_error(@() wrc.equilibrium(ws, 'y', 3e-3, 'yaw', 0, 'Q', 200e3, 'max_iterations', 1, 'force_tolerance', 1e-15), ...
             'wrc:notConverged', '.', 'not converged, one output');
[e, ok] = wrc.equilibrium(ws, 'y', 3e-3, 'yaw', 0, 'Q', 200e3, 'max_iterations', 1, 'force_tolerance', 1e-15);
expect_true(~ok && e.converged == 0 && ischar(e.error) && ~isempty(e.error), 'not converged, [e, ok]: the result');

% Lifetime: freed objects are refused; a wheelset outlives the profiles it was made from; clearing releases.
before = wrc_mex('live');
p = wrc.profile_load('profiles/s1002.lua');
r = wrc.profile_load('profiles/60e1.lua');
w2 = wrc.wheelset('wheel', p, 'rail', r);
tr = w2.trajectory();
expect_rel(wrc_mex('live'), before + 4, 0, 'four objects made');
wrc.free(p, r);
expect_true(strcmp(p.kind(), 'freed'), 'a freed profile says so');
expect_error(@() p.points(), 'wrc:freed', 'this profile was freed', 'a freed profile used');
expect_error(@() wrc.wheelset('wheel', p, 'rail', rail), 'wrc:freed', 'this profile was freed', 'a freed profile in a wheelset');
expect_error(@() wrc.free(p), 'wrc:freed', 'freed already', 'a profile freed twice');
c = w2.contact(pose{:});
expect_true(c.force.z > 0, 'the wheelset works after its profiles were freed');
w2.free();
expect_error(@() w2.contact(pose{:}), 'wrc:freed', 'this wheelset was freed', 'a freed wheelset used');
s = tr.contact(pose{:});
expect_true(s.force.z > 0, 'a trajectory works after its wheelset was freed (it keeps it alive)');
tr.free();
expect_error(@() tr.contact(pose{:}), 'wrc:freed', 'this trajectory was freed', 'a freed trajectory used');
expect_error(@() tr.reset(), 'wrc:freed', 'this trajectory was freed', 'a freed trajectory reset');
expect_rel(wrc_mex('live'), before, 0, 'all four released');
q = wrc.profile_load('profiles/s1002.lua');
expect_rel(wrc_mex('live'), before + 1, 0, 'one made');
clear q;
expect_rel(wrc_mex('live'), before, 0, 'clearing the last variable releases the object');
q = wrc.profile_load('profiles/s1002.lua');
delete(q);
expect_rel(wrc_mex('live'), before, 0, 'delete releases the object');
clear q;  % the destructor again, on a freed object: quiet

% The MEX file stays loaded while an object lives; an id of an object freed before the MEX file was cleared is
% refused after it is loaded again, also when a new object is made (ids are not reused across loadings).
q = wrc.profile_load('profiles/s1002.lua');
clear functions;  % unloads an unlocked MEX file (Octave's `clear mex` does not)
[qy, ~] = q.points();
expect_true(numel(qy) > 100, 'clear functions keeps a live object');
old = q.id;
clear q;
wrc.free(ws, wheel, rail);
expect_rel(wrc_mex('live'), 0, 0, 'every object released');
clear functions;  % unloaded now: nothing holds it
made = {};  % as many objects as the old id's serial number: one would take the old id if ids were reused
for k = 1:double(bitand(old, uint64(4294967295)))
  made{k} = wrc.profile_points('kind', 'rail', 'y', [0 1e-3 2e-3], 'z', [0 0 0]);
  expect_true(made{k}.id ~= old, 'a new id after the MEX file was loaded again');
end
expect_error(@() wrc_mex('points', old), 'wrc:freed', 'not a live wrc object|was freed', 'an id of a cleared loading');
clear made q;
three = {'kind', 'rail', 'y', [0 1e-3 2e-3], 'z', [0 0 0]};
for k = 1:3  % loaded, one object made and freed, cleared, loaded again: within a second, as fast as it goes
  expect_rel(wrc_mex('live'), 0, 0, 'nothing alive');
  clear functions;
  a = wrc.profile_points(three{:});
  first = a.id;
  clear a;
  clear functions;
  b = wrc.profile_points(three{:});
  expect_true(b.id ~= first, 'the first id of a loading differs from the first of the loading before');
  clear b;
end
disp('test_bad_input: all checks hold');
