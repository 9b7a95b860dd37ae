% Frictionless Hertz contact through the MEX interface against Hertz's solution computed here (hertz_reference.m):
% a cylindrical wheel (flat profile, r0 = 450 mm) on a crowned rail (a circular arc of transverse radius R, cant 0),
% both made with wrc.profile_points. Curvatures A = 1/(2 r0) along the track, B = 1/(2 R) across. The centred
% wheelset touches at z = 0 on the crown, so the pose z = -delta presses in by delta: Hertz gives the force and the
% peak pressure. With R = r0 / 5 the area is an ellipse about three times longer along the track than across: the
% pressure matrix's loaded extent along its columns (x) and rows (y) must match a and b, which a grid handed over
% transposed would not. (tests/scripts/contact_hertz.lua makes the same comparison in Lua, on more grids.)
E = 2.1e11; nu = 0.3; Estar = E / (2 * (1 - nu^2));
r0 = 0.45; F = 100e3; gauge_depth = 0.2e-3; step = 0.02e-3;
wheel = wrc.profile_points('kind', 'wheel', 'y', -0.070 + (0:130) * 1e-3, 'z', zeros(1, 131), 'name', 'cylinder');
for q = [1 5]
  R = r0 / q;
  yr = (-1250:1250) * step;
  rail = wrc.profile_points('kind', 'rail', 'y', yr, 'z', sqrt(R^2 - yr.^2) - R);
  ref = hertz_reference(1 / (2 * r0), 1 / (2 * R), Estar, F);
  yg = sqrt(R^2 - (R - gauge_depth)^2);  % the gauge point on the crown's gauge side
  ws = wrc.wheelset('wheel', wheel, 'rail', rail, 'radius', r0, 'cant', 0, 'gauge_depth', gauge_depth, ...
                    'gauge', 2 * (0.75 - yg), 'E', E, 'nu', nu, 'grid', min(ref.a, ref.b) / 8, ...
                    'strategy', 'coarse+topology');
  c = wrc.contact(ws, 'y', 0, 'z', -ref.delta, 'roll', 0, 'yaw', 0);
  what = sprintf('B/A = %g: ', q);
  expect_true(numel(c.left.patches) == 1 && numel(c.right.patches) == 1, [what 'one area per wheel']);
  p = c.left.patches(1);
  expect_rel(p.normal_force, F, 0.01, [what 'normal force within 1 % of Hertz']);
  expect_rel(p.pmax, ref.p0, 0.02, [what 'peak pressure within 2 % of Hertz']);
  g = p.grid;
  expect_rel(sum(p.pressure(:)) * g.dx * g.dy, p.pressure_integral, 1e-9, [what 'the grid sums to the pressure integral']);
  expect_rel(max(p.pressure(:)), p.pmax, 1e-12, [what 'the grid''s largest element is pmax']);
  [~, at] = max(p.pressure(:));
  [jc, ic] = ind2sub(size(p.pressure), at);
  along_x = 0.5 * nnz(p.pressure(jc, :) > 0) * g.dx;
  along_y = 0.5 * nnz(p.pressure(:, ic) > 0) * g.dy;
  expect_true(abs(along_x - ref.a) <= g.dx, sprintf('%sloaded half-length along x %.3f mm, Hertz a %.3f mm', what, along_x * 1e3, ref.a * 1e3));
  expect_true(abs(along_y - ref.b) <= g.dy, sprintf('%sloaded half-width along y %.3f mm, Hertz b %.3f mm', what, along_y * 1e3, ref.b * 1e3));
  [x, y] = wrc.grid_axes(p);
  expect_true(numel(x) == g.nx && numel(y) == g.ny && abs(x(ic) - (p.point.x - p.frame.origin.x)) <= g.dx, ...
              [what 'wrc.grid_axes: the centre of pressure in the peak''s column']);
  printf('%sF %.4f %% and pmax %.4f %% off Hertz; half-axes %.3f / %.3f mm (Hertz %.3f / %.3f)\n', what, ...
         100 * (p.normal_force / F - 1), 100 * (p.pmax / ref.p0 - 1), along_x * 1e3, along_y * 1e3, ref.a * 1e3, ref.b * 1e3);
end

% A grid too coarse for the contact: the sphere on a plane (R = r0) on elements of 1.055 a spans 3 elements each way,
% its pmax is far above Hertz's p0, and a MATLAB warning wrc:resolutionWarning says so once for the wheelset (two
% calls and a trajectory's step), naming a grid that resolves it; on elements of a / 4 nothing is said.
rail = wrc.profile_points('kind', 'rail', 'y', yr, 'z', sqrt(r0^2 - yr.^2) - r0);
ref = hertz_reference(1 / (2 * r0), 1 / (2 * r0), Estar, F);
yg = sqrt(r0^2 - (r0 - gauge_depth)^2);
pair = {'wheel', wheel, 'rail', rail, 'radius', r0, 'cant', 0, 'gauge_depth', gauge_depth, 'gauge', 2 * (0.75 - yg), ...
        'E', E, 'nu', nu, 'strategy', 'coarse+topology'};
pose = {'y', 0, 'z', -ref.delta, 'roll', 0, 'yaw', 0};
coarse = wrc.wheelset(pair{:}, 'grid', 1.055 * ref.a);
lastwarn('', '');
c = wrc.contact(coarse, pose{:});
[msg, id] = lastwarn();
expect_true(strcmp(id, 'wrc:resolutionWarning') && ~isempty(strfind(msg, 'spans only 3 x 3 elements')) && ...
            ~isempty(strfind(msg, 'or finer spans it')), ['a contact 3 elements wide: the warning, got ''' msg '''']);
p = c.left.patches(1);
expect_true(~p.resolved && p.span.x == 3 && p.span.y == 3, 'a contact 3 elements wide: resolved false, span 3 x 3');
expect_true(p.pmax / ref.p0 - 1 > 0.1, sprintf('a contact 3 elements wide: pmax %.1f %% off Hertz', 100 * (p.pmax / ref.p0 - 1)));
lastwarn('', '');
again = wrc.contact(coarse, pose{:});
tr = coarse.trajectory();
step = tr.contact(pose{:});
[msg, id] = lastwarn();
expect_true(isempty(id) && isempty(msg) && ~again.left.patches(1).resolved && ~step.left.patches(1).resolved, ...
            ['once per wheelset, its trajectory included; got ''' msg '''']);
fine = wrc.wheelset(pair{:}, 'grid', ref.a / 4);
lastwarn('', '');
c = wrc.contact(fine, pose{:});
p = c.left.patches(1);
[msg, id] = lastwarn();
expect_true(isempty(id) && p.resolved, ['elements of a / 4: resolved, no warning; got ''' msg '''']);
expect_rel(p.pmax, ref.p0, 0.033, 'elements of a / 4: pmax within 3.3 % of Hertz');
disp('test_hertz: all checks hold');
