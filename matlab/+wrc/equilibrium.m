function varargout = equilibrium(ws, varargin)
%WRC.EQUILIBRIUM  The static equilibrium of the wheelset under the vertical load Q (N): z and roll solved at y, yaw.
%   e = wrc.equilibrium(ws, 'y', 3e-3, 'yaw', 0, 'Q', 200e3)   (or ws.equilibrium(...))
%   y, yaw and Q are the arguments of wrc_equilibrium: each is required. Other keys as Lua's ws:equilibrium: grids,
%   force_tolerance, moment_tolerance, max_iterations, max_evaluations, max_penetration, start.z, start.roll.
%   e.Y_Q, e.z, e.roll, e.left.patches(k).pmax, ... (docs/reference/fields.md).
%   [e, ok] = wrc.equilibrium(...) returns a solve that did not converge (ok false, e.error) instead of an error.
  [varargout{1:max(1, nargout)}] = wrc_mex('equilibrium', wrc.Handle.id_of(ws), varargin{:});
end
