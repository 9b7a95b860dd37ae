function [x, y] = grid_axes(patch)
%WRC.GRID_AXES  The coordinates (m) of a contact area's grid, for its ny-by-nx matrices (pressure, h, px, ...):
%   [x, y] = wrc.grid_axes(c.left.patches(1)); imagesc(x, y, c.left.patches(1).pressure)
%   x along the area's t1 (rolling direction), y along t2, from the frame's origin (patch.frame).
  g = patch.grid;
  x = g.x0 + (0:g.nx - 1) * g.dx;
  y = g.y0 + (0:g.ny - 1)' * g.dy;
end
