% Equivalent conicity through the MEX interface against cases whose answer is known without the engine:
%  - a Δr table of a cone pair, Δr = 2 tan(gamma) y: tan(gamma_e) = tan(gamma) at every amplitude, by every method;
%  - a coned wheel (1:20) on 60E1 without cant, roll fixed: the contact stays where the rail's slope is 1:20, so the
%    wheelset's own Δr is 2 y / 20 and tan(gamma_e) = 0.05 (tests/scripts/kinematics_conicity.lua, in Lua);
%  - wrc.conicity(ws, ...) equals wrc.conicity on the Δr table the wheelset returns with its result.
methods = {'integral', 'harmonic', 'regression', 'simple'};
yhat = [0.5e-3 1e-3 2e-3 3e-3 5e-3];
y = (-200:200)' * 0.05e-3;
for k = 1:numel(methods)
  t = wrc.conicity('y', y, 'dr', 2 * 0.05 * y, 'yhat', yhat, 'method', methods{k});
  expect_rel(t.tan_gamma, 0.05 * ones(5, 1), 1e-9, ['cone pair Δr table, ' methods{k}]);
  expect_rel(t.yhat, yhat', 0, ['the amplitudes come back, ' methods{k}]);
  expect_true(strcmp(t.method, methods{k}), ['the method comes back as a string, ' methods{k}]);
end

rail = wrc.profile_load('profiles/60e1.lua');
s = (-30:0.1:40)' * 1e-3;
cone = wrc.profile_points('kind', 'wheel', 'name', 'cone 1:20', 'y', s, 'z', s / 20);
ws = wrc.wheelset('wheel', cone, 'rail', rail, 'cant', 0);
for k = 1:numel(methods)
  t = ws.conicity('yhat', yhat, 'method', methods{k});
  expect_true(all(abs(t.tan_gamma - 0.05) <= 2e-5), sprintf('cone 1:20 on 60E1, %s: %s', methods{k}, mat2str(t.tan_gamma', 6)));
end

[ws2] = paper_wheelset();
t = wrc.conicity(ws2, 'yhat', [1e-3 2e-3 3e-3 4e-3]);
again = wrc.conicity('y', t.dr.y, 'dr', t.dr.dr, 'yhat', [1e-3 2e-3 3e-3 4e-3]);
expect_rel(again.tan_gamma, t.tan_gamma, 1e-15, 'ws conicity = wrc.conicity on its own Δr table');
expect_true(numel(t.dr.y) == numel(t.dr.flange) && all(diff(t.dr.y) > 0), 'the Δr table: y increasing, a flag per y');
disp('test_conicity: all checks hold');
