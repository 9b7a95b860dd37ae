function p = profile_load(path, varargin)
%WRC.PROFILE_LOAD  Loads a wheel or rail profile: a Lua definition or a file a reader plugin reads.
%   p = wrc.profile_load('profiles/s1002.lua')          a profile shipped with wrc
%   p = wrc.profile_load('w1.txt', 'units', 'mm', 'mirror_y', true)
%   Options (name/value pairs or a struct; nested structs give dotted keys, e.g. struct('shift', struct('y', 1e-3)))
%   are those of Lua's wrc.profile.load: units, mirror_y, mirror_z, crop.y, crop.z, shift.y, shift.z, kind, name,
%   reader and the reader's own. Returns a wrc.ProfileHandle. docs/matlab.md; docs/guide/profiles.md.
  p = wrc.ProfileHandle(wrc_mex('profile_load', path, varargin{:}));
end
