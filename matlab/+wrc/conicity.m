function c = conicity(varargin)
%WRC.CONICITY  Equivalent conicity (EN 15302): of a wheelset, or of a Δr table.
%   c = wrc.conicity(ws, 'yhat', [1e-3 3e-3], 'roll', 'fixed')   the wheelset's own rigid Δr table (ws:conicity)
%   c = wrc.conicity('y', y, 'dr', dr, 'yhat', 3e-3, 'method', 'integral')   any table: y (m, increasing) and
%                                                                   dr = r_left - r_right (m) (Lua's wrc.conicity)
%   Keys as in Lua: yhat, method (integral, harmonic, regression, simple), r0, contact_distance; for a wheelset
%   also roll, y.from/to/step, yaw, threads, flange_angle. c.tan_gamma (one per amplitude), c.yhat, c.wavelength;
%   a wheelset's also c.dr.y, c.dr.dr, c.dr.flange.
  if nargin > 0 && isa(varargin{1}, 'wrc.WheelsetHandle')
    c = wrc_mex('wheelset_conicity', varargin{1}.id, varargin{2:end});
  else
    c = wrc_mex('conicity', varargin{:});
  end
end
