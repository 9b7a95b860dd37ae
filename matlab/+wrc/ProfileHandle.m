classdef ProfileHandle < wrc.Handle
%WRC.PROFILEHANDLE  A wheel or rail profile: made by wrc.profile_load or wrc.profile_points.
%   [y, z] = p.points()                     the points (m, column vectors; left-side frame)
%   p.write(path, 'format', 'csv', ...)     writes it in a format wrc reads back (options of p:write)
%   m = p.flange_measures('tape_offset', 0.07)   EN 15313 Sh, Sd, qR (a struct)
%   p.free()                                releases it now (also: wrc.free(p), or clearing the last variable)
  methods
    function obj = ProfileHandle(id)
      obj.id = id;
    end
    function [y, z] = points(p)
      [y, z] = wrc_mex('points', p.id);
    end
    function write(p, path, varargin)
      wrc_mex('write', p.id, path, varargin{:});
    end
    function m = flange_measures(p, varargin)
      m = wrc.flange_measures(p, varargin{:});
    end
  end
end
