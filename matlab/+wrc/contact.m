function varargout = contact(ws, varargin)
%WRC.CONTACT  Contact at a prescribed pose (m, rad): the normal problems of every area, and creep forces when rolling.
%   c = wrc.contact(ws, 'y', 3e-3, 'z', -2e-5, 'roll', 0, 'yaw', 0)   (or ws.contact(...))
%   y, z, roll and yaw are the arguments of the C function wrc_contact: each is required. Other keys as Lua's
%   ws:contact: grids, sensitivity, max_penetration, search, and the rolling keys V, omega, vy, yaw_rate,
%   slip_reference, creepage.xi/eta/phi, mu (or mu_static, mu_kinetic), method, rolling_tolerance.
%   c is a struct with the Lua result's fields (docs/reference/fields.md): c.force.z, c.left.patches(1).pmax, grids
%   as ny-by-nx matrices (c.left.patches(1).pressure; wrc.grid_axes gives their coordinates).
%   [c, ok] = wrc.contact(...) returns a solve that did not converge (ok false, c.error) instead of an error.
  [varargout{1:max(1, nargout)}] = wrc_mex('contact', wrc.Handle.id_of(ws), varargin{:});
end
