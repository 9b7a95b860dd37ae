function varargout = wheel(ws, varargin)
%WRC.WHEEL  One wheel with its vertical contact force Fz (N) prescribed at y, yaw, roll (m, rad).
%   w = wrc.wheel(ws, 'side', 'left', 'y', 3e-3, 'yaw', 0, 'roll', 0, 'Fz', 100e3)   (or ws.wheel(...))
%   side, y, yaw, roll and Fz are the arguments of wrc_wheel: each is required. Other keys as Lua's ws:wheel:
%   force_tolerance, max_iterations, max_evaluations, max_penetration, grids and the rolling keys of wrc.contact.
%   [w, ok] = wrc.wheel(...) returns a solve that did not converge (ok false) instead of an error.
  [varargout{1:max(1, nargout)}] = wrc_mex('wheel', wrc.Handle.id_of(ws), varargin{:});
end
