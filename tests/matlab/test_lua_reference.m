% The MEX interface against the Lua executable: the same calls (tests/matlab/reference.lua) give the same numbers, bit
% for bit -- both are requests of the engine's one call layer; here through the C API, the MEX file's option text
% and its reading of result paths into structs. A grid read with its rows and columns swapped, a list index off by
% one, an option lost or a number rounded on the way fails here.
here = fileparts(mfilename('fullpath'));
[status, text] = system(sprintf('"%s" run "%s"', getenv('WRC_BIN'), fullfile(here, 'reference.lua')));
expect_true(status == 0, ['wrc run reference.lua: ' text]);
lines = strsplit(strtrim(text), "\n");
lua = struct();
for k = 1:numel(lines)
  parts = strsplit(strtrim(lines{k}), ' ');
  lua.(strrep(parts{1}, '.', '_')) = str2double(parts{2});
end

[ws, wheel] = paper_wheelset();
e = wrc.equilibrium(ws, 'y', 3e-3, 'yaw', 0, 'Q', 200e3);
expect_rel(e.Y_Q, lua.equilibrium_Y_Q, 0, 'equilibrium Y/Q');
expect_rel(e.z, lua.equilibrium_z, 0, 'equilibrium z');
expect_rel(e.roll, lua.equilibrium_roll, 0, 'equilibrium roll');
expect_rel(e.left.force.z, lua.equilibrium_left_force_z, 0, 'equilibrium left.force.z');
expect_rel(numel(e.left.patches), lua.equilibrium_patches, 0, 'equilibrium: number of left patches');
expect_rel(e.left.patches(1).pmax, lua.equilibrium_left_patches_1_pmax, 0, 'equilibrium left.patches(1).pmax');

c = wrc.contact(ws, 'y', 2e-3, 'z', e.z, 'roll', e.roll, 'yaw', 2e-3);
p = c.left.patches(1);
expect_rel(c.force.y, lua.contact_force_y, 0, 'contact force.y');
expect_rel(c.force.z, lua.contact_force_z, 0, 'contact force.z');
expect_rel([p.grid.nx p.grid.ny], [lua.contact_nx lua.contact_ny], 0, 'contact grid size');
expect_rel(size(p.pressure), [p.grid.ny p.grid.nx], 0, 'a grid is ny-by-nx');
j = floor((p.grid.ny + 1) / 2);
i = floor((p.grid.nx + 1) / 2);
expect_rel(p.pressure(j, i), lua.contact_p_centre, 0, 'pressure(j, i) = Lua''s pressure[j][i]');
expect_rel(p.pressure(j + 1, i), lua.contact_p_j1, 0, 'pressure(j + 1, i): rows along the grid''s y');
expect_rel(p.pressure(j, i + 3), lua.contact_p_i3, 0, 'pressure(j, i + 3): columns along the grid''s x');

r = ws.contact('y', 2e-3, 'z', e.z, 'roll', e.roll, 'yaw', 0, 'V', 30, 'creepage', struct('xi', 1e-3 / 3), 'mu', 0.3);
expect_rel(r.force.x, lua.rolling_force_x, 0, 'rolling contact force.x (creepage as a nested struct)');
expect_rel(r.left.patches(1).Fx, lua.rolling_left_patches_1_Fx, 0, 'rolling contact left.patches(1).Fx');
r2 = ws.contact('y', 2e-3, 'z', e.z, 'roll', e.roll, 'yaw', 0, 'V', 30, 'creepage.xi', 1e-3 / 3, 'mu', 0.3);
expect_rel(r2.force.x, lua.rolling_force_x, 0, 'rolling contact force.x (creepage.xi as a dotted key)');

w = wrc.wheel(ws, 'side', 'right', 'y', 3e-3, 'yaw', 0, 'roll', 0, 'Fz', 100e3);
expect_rel(w.force.y, lua.wheel_force_y, 0, 'wheel force.y');
expect_rel(w.force.z, lua.wheel_force_z, 0, 'wheel force.z');

g = wrc.rigid(ws, 'y', 3e-3, 'yaw', 0);
expect_rel(g.z, lua.rigid_z, 0, 'rigid z');
expect_rel(g.roll, lua.rigid_roll, 0, 'rigid roll');
expect_rel(g.rolling_radius_difference, lua.rigid_dr, 0, 'rigid rolling_radius_difference');
expect_rel(g.left.rolling_radius, lua.rigid_left_rolling_radius, 0, 'rigid left.rolling_radius');

t = wrc.conicity(ws, 'yhat', [1e-3 3e-3]);
expect_rel(t.tan_gamma, [lua.ws_conicity_1; lua.ws_conicity_2], 0, 'wheelset conicity (a column per amplitude)');

y = (-100:100)' * 1e-4;
tc = wrc.conicity('y', y, 'dr', 0.1 * y + 300 * y.^3, 'yhat', [2e-3 5e-3], 'method', 'harmonic');
expect_rel(tc.tan_gamma, [lua.conicity_1; lua.conicity_2], 0, 'conicity of a Δr table');

m = wheel.flange_measures();
expect_rel([m.Sh m.Sd m.qR], [lua.flange_Sh lua.flange_Sd lua.flange_qR], 0, 'flange measures Sh, Sd, qR');

gt = wrc.geometry_table(ws, 'y', struct('from', -5e-3, 'to', 5e-3, 'step', 1e-3), 'roll', 'fixed', 'threads', 1);
expect_rel(numel(gt.rows), lua.table_rows, 0, 'geometry table: rows');
expect_rel(gt.rows(4).rolling_radius_difference, lua.table_rows_4_dr, 0, 'geometry table rows(4)');

tr = ws.trajectory('tolerance', 1e-6);
tr.contact('y', 1e-3, 'z', e.z, 'roll', e.roll, 'yaw', 0);
s2 = tr.contact('y', 1.1e-3, 'z', e.z, 'roll', e.roll, 'yaw', 0);
expect_rel(s2.force.z, lua.trajectory_force_z, 0, 'trajectory: the second step, warm from the first');
disp('test_lua_reference: all checks hold');
