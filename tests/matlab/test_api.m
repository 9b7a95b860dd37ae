% Every function of the +wrc package and every method of its objects, each with a check that does not come from the
% engine's own output: round trips, force balances, symmetries, equal answers by two routes.
expect_true(~isempty(regexp(wrc.version(), '^\d+\.\d+\.\d+$', 'once')), 'wrc.version');

% Profiles: points in, points out; options; write and read back.
y = (-20:0.5:20)' * 1e-3;
z = 1e-3 * sin(y / 5e-3) + y / 40;
p = wrc.profile_points('kind', 'wheel', 'y', y, 'z', z, 'name', 'wavy');
[py, pz] = p.points();
expect_rel([py pz], [y z], 0, 'profile_points -> points: the same numbers');
expect_true(strcmp(p.kind(), 'profile'), 'kind');
shifted = wrc.profile_points('kind', 'wheel', 'y', y + 1e-3, 'z', z);
[sy, ~] = shifted.points();
expect_rel(sy, y + 1e-3, 1e-15, 'a shifted copy');
s1002 = wrc.profile_load('profiles/s1002.lua');
moved = wrc.profile_load('profiles/s1002.lua', struct('shift', struct('y', 2e-3)));
[y0, z0] = s1002.points();
[y1, z1] = moved.points();
expect_rel(y1, y0 + 2e-3, 1e-12, 'profile_load with shift.y (a nested struct) moves the points by it');
expect_rel(z1, z0, 0, 'shift.y leaves z');
file = fullfile(getenv('WRC_TEST_TMP'), 'matlab_wavy.csv');
p.write(file);
back = wrc.profile_load(file, 'kind', 'wheel');
[by, bz] = back.points();
expect_true(numel(by) == numel(y) && max(abs(by - y)) < 1e-9 && max(abs(bz - z)) < 1e-9, 'write, load: the points back');

% A loaded profile's warnings are MATLAB warnings (wrc:profileWarning): S1002 with 2 um of scatter added to z, written
% in mm, is loaded with the scatter's warning (docs/guide/profiles.md); the clean points are not.
randn('state', 1);
noisy = fullfile(getenv('WRC_TEST_TMP'), 'matlab_scattered.txt');
f = fopen(noisy, 'w');
fprintf(f, '%.6f %.6f\n', [y0 (z0 + 2e-6 * randn(size(z0)))]' * 1e3);
fclose(f);
lastwarn('', '');
wrc.profile_load(noisy, 'kind', 'wheel');
[msg, id] = lastwarn();
expect_true(strcmp(id, 'wrc:profileWarning') && ~isempty(strfind(msg, 'smooth = 0.5e-3')), ...
            ['a scattered profile: a MATLAB warning naming the remedy, got ''' msg '''']);
lastwarn('', '');
wrc.profile_load(noisy, 'kind', 'wheel', 'smooth', 0.5e-3);
wrc.profile_load(file, 'kind', 'wheel');
[msg, id] = lastwarn();
expect_true(isempty(id) && isempty(msg), ['smoothed, and clean points: no warning, got ''' msg '''']);
% The same scattered points given as arrays (wrc.profile_points, the polyline through them): the same warning.
wrc.profile_points('kind', 'wheel', 'y', y0, 'z', z0 + 2e-6 * randn(size(z0)));
[msg, id] = lastwarn();
expect_true(strcmp(id, 'wrc:profileWarning') && ~isempty(strfind(msg, 'Make it with a smoothing length')), ...
            ['scattered points given as arrays: the warning, got ''' msg '''']);

% Flange measures: the function and the method; S1002's nominal Sh 28 mm, Sd 32.5 mm (EN 15313).
m = wrc.flange_measures(s1002);
expect_true(isequal(m, s1002.flange_measures()), 'flange_measures: function = method');
expect_rel([m.Sh m.Sd], [28e-3 32.5e-3], 1e-6, 'S1002: Sh 28 mm, Sd 32.5 mm');

% Wheelsets: from two profiles and from four (the same four): the same wheelset.
[ws, wheel, rail] = paper_wheelset();
ws4 = wrc.wheelset('left_wheel', wheel, 'right_wheel', wheel, 'left_rail', rail, 'right_rail', rail, ...
                   struct('gauge', 1.435, 'cant', 0.025, 'radius', 0.45));
e = wrc.equilibrium(ws, 'y', 3e-3, 'yaw', 0, 'Q', 200e3);
e4 = ws4.equilibrium('y', 3e-3, 'yaw', 0, 'Q', 200e3);
expect_rel([e4.z e4.roll e4.Y], [e.z e.roll e.Y], 0, 'four profiles (the same ones) = two');
expect_true(e.converged == 1, 'equilibrium converged');
expect_rel(e.left.force.z + e.right.force.z, 200e3, 1e-6, 'equilibrium: the wheels carry Q');
expect_rel(e.Y, -(e.left.force.y + e.right.force.y), 1e-12, 'equilibrium: Y = -sum Fy');
expect_true(isequal(e, ws.equilibrium('y', 3e-3, 'yaw', 0, 'Q', 200e3)), 'ws.equilibrium = wrc.equilibrium');

% Contact: the centred wheelset is symmetric; grids only when asked; no contact gives empty lists.
c = wrc.contact(ws, 'y', 0, 'z', -2e-5, 'roll', 0, 'yaw', 0);
expect_rel(c.right.force.z, c.left.force.z, 1e-9, 'centred: right = left');
expect_true(isstruct(c.left.patches) && numel(c.left.patches) >= 1, 'patches: a struct array');
expect_true(isfield(c.left.patches(1), 'pressure'), 'grids by default');
ng = ws.contact('y', 0, 'z', -2e-5, 'roll', 0, 'yaw', 0, 'grids', false);
expect_true(~isfield(ng.left.patches(1), 'pressure'), 'grids = false: no grid');
expect_rel(ng.force.z, c.force.z, 0, 'grids = false: the same forces');
off = ws.contact('y', 0, 'z', 1e-3, 'roll', 0, 'yaw', 0);
expect_true(isempty(off.left.patches) && off.force.z == 0, 'lifted off: no patches, no force');

% One wheel with Fz given: Fz is met.
w = wrc.wheel(ws, 'side', 'left', 'y', 2e-3, 'yaw', 0, 'roll', 0, 'Fz', 90e3);
expect_rel(w.force.z, 90e3, 1e-3, 'wheel: Fz met');
expect_true(isequal(w, ws.wheel('side', 'left', 'y', 2e-3, 'yaw', 0, 'roll', 0, 'Fz', 90e3)), 'ws.wheel = wrc.wheel');

% Rigid contact: centred, Δr = 0 and both wheels alike; the table's rows are the single calls.
g0 = wrc.rigid(ws, 'y', 0, 'yaw', 0, 'roll', 'fixed');
expect_true(abs(g0.rolling_radius_difference) < 1e-12, 'rigid, centred: Δr = 0');
t = ws.geometry_table('y', [-2e-3 0 2e-3], 'roll', 'fixed');
expect_true(numel(t.rows) == 3 && isstruct(t.rows), 'geometry table: a struct array of rows');
g2 = ws.rigid('y', 2e-3, 'yaw', 0, 'roll', 'fixed');
expect_rel(t.rows(3).rolling_radius_difference, g2.rolling_radius_difference, 0, 'table row 3 = rigid at y = 2 mm');
expect_rel(t.rows(1).rolling_radius_difference, -g2.rolling_radius_difference, 1e-9, 'symmetric: Δr(-y) = -Δr(y)');

% Trajectories: reset forgets the steps (the same steps again give the same numbers); wheel steps meet Fz.
tr = wrc.trajectory(ws, 'tolerance', 1e-6);
a1 = tr.contact('y', 1e-3, 'z', e.z, 'roll', e.roll, 'yaw', 0);
a2 = tr.contact('y', 1.2e-3, 'z', e.z, 'roll', e.roll, 'yaw', 0);
tr.reset();
b1 = tr.contact('y', 1e-3, 'z', e.z, 'roll', e.roll, 'yaw', 0);
b2 = tr.contact('y', 1.2e-3, 'z', e.z, 'roll', e.roll, 'yaw', 0);
expect_rel([b1.force.z b2.force.z], [a1.force.z a2.force.z], 0, 'trajectory reset: the same steps, the same numbers');
cold = wrc.contact(ws, 'y', 1.2e-3, 'z', e.z, 'roll', e.roll, 'yaw', 0);
expect_rel(b2.force.z, cold.force.z, 1e-5, 'a warm step = the cold call, to the tolerance');
tw = tr.wheel('side', 'right', 'y', 1e-3, 'yaw', 0, 'roll', 0, 'Fz', 80e3);
expect_rel(tw.force.z, 80e3, 1e-3, 'trajectory wheel: Fz met');

% Conicity: both forms (test_conicity.m checks the numbers).
k = wrc.conicity(ws, 'yhat', 3e-3);
expect_true(isfield(k, 'tan_gamma'), 'wrc.conicity(ws, ...)');
[x, yy] = wrc.grid_axes(c.left.patches(1));
expect_true(isrow(x) && iscolumn(yy) && numel(x) == c.left.patches(1).grid.nx, 'grid_axes: x a row, y a column');
wrc.free(p, shifted, s1002, moved, back, ws4, tr);
disp('test_api: all checks hold');
