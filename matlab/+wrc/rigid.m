function varargout = rigid(ws, varargin)
%WRC.RIGID  The rigid contact at y, yaw (m, rad): contact points, rolling radii, Δr (Lua's ws:rigid).
%   g = wrc.rigid(ws, 'y', 3e-3, 'yaw', 0, 'roll', 'fixed')   (or ws.rigid(...))
%   y and yaw are the arguments of wrc_rigid_contact: both are required. Other keys: roll ('free', 'fixed' or a
%   number), Q, two_point_tolerance, start.z, start.roll. g.rolling_radius_difference,
%   g.left.contacts(1).rolling_radius, ...; [g, ok] = wrc.rigid(...) when there may be no such pose.
  [varargout{1:max(1, nargout)}] = wrc_mex('rigid', wrc.Handle.id_of(ws), varargin{:});
end
