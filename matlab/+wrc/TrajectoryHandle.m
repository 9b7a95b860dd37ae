classdef TrajectoryHandle < wrc.Handle
%WRC.TRAJECTORYHANDLE  A wheelset followed along time steps (wrc.trajectory); each step starts from the steps before.
%   r = tr.contact('y', y, 'z', z, 'roll', roll, 'yaw', yaw, ...)   as wrc.contact, warm (the rolling keys too)
%   w = tr.wheel('side', 'left', 'y', y, 'yaw', yaw, 'roll', roll, 'Fz', Fz, ...)
%   tr.reset()                                                       forgets the steps before
  methods
    function obj = TrajectoryHandle(id)
      obj.id = id;
    end
    function varargout = contact(tr, varargin)
      [varargout{1:max(1, nargout)}] = wrc_mex('trajectory_contact', tr.id, varargin{:});
    end
    function varargout = wheel(tr, varargin)
      [varargout{1:max(1, nargout)}] = wrc_mex('trajectory_wheel', tr.id, varargin{:});
    end
    function reset(tr)
      wrc_mex('trajectory_reset', tr.id);
    end
  end
end
