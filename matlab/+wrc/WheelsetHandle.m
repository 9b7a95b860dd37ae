classdef WheelsetHandle < wrc.Handle
%WRC.WHEELSETHANDLE  A wheelset made by wrc.wheelset; its methods are the package's functions:
%   ws.contact(...), ws.wheel(...), ws.equilibrium(...), ws.rigid(...), ws.geometry_table(...), ws.conicity(...),
%   ws.trajectory(...) are wrc.contact(ws, ...), ... (help wrc.contact).
  methods
    function obj = WheelsetHandle(id)
      obj.id = id;
    end
    function varargout = contact(ws, varargin)
      [varargout{1:max(1, nargout)}] = wrc.contact(ws, varargin{:});
    end
    function varargout = wheel(ws, varargin)
      [varargout{1:max(1, nargout)}] = wrc.wheel(ws, varargin{:});
    end
    function varargout = equilibrium(ws, varargin)
      [varargout{1:max(1, nargout)}] = wrc.equilibrium(ws, varargin{:});
    end
    function varargout = rigid(ws, varargin)
      [varargout{1:max(1, nargout)}] = wrc.rigid(ws, varargin{:});
    end
    function t = geometry_table(ws, varargin)
      t = wrc.geometry_table(ws, varargin{:});
    end
    function c = conicity(ws, varargin)
      c = wrc.conicity(ws, varargin{:});
    end
    function tr = trajectory(ws, varargin)
      tr = wrc.trajectory(ws, varargin{:});
    end
  end
end
