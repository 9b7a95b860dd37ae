function p = profile_points(varargin)
%WRC.PROFILE_POINTS  A profile from points: wrc.profile_points('kind', 'wheel', 'y', y, 'z', z, 'name', 'w1').
%   y, z in m (left-side frame, docs/design.md section 2), kind 'wheel' or 'rail', name optional. Returns a
%   wrc.ProfileHandle.
  p = wrc.ProfileHandle(wrc_mex('profile_points', varargin{:}));
end
