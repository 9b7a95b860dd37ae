function tr = trajectory(ws, varargin)
%WRC.TRAJECTORY  A wheelset followed along time steps (a multibody code's calls): a wrc.TrajectoryHandle.
%   tr = wrc.trajectory(ws, 'tolerance', 1e-6, 'grids', false, 'extrapolate', true)
%   then r = tr.contact('y', .., 'z', .., 'roll', .., 'yaw', ..), w = tr.wheel(...), tr.reset() (help
%   wrc.TrajectoryHandle; docs/guide/online.md).
  tr = wrc.TrajectoryHandle(wrc_mex('trajectory', wrc.Handle.id_of(ws), varargin{:}));
end
