% wrc -- wheel-rail contact (the wrc engine) from MATLAB and Octave, through the C API (docs/matlab.md).
%
% Profiles and wheelsets (handle objects; released when cleared, or by wrc.free)
%   profile_load    - a profile from a Lua definition or a file ('profiles/s1002.lua', 'w1.txt', ...)
%   profile_points  - a profile from points (m)
%   flange_measures - EN 15313 Sh, Sd, qR of a wheel profile
%   wheelset        - a wheelset from one wheel and one rail profile, or from four
%   free            - releases objects now
%
% Solves (the Lua API's keys as name/value pairs or a struct; results are structs with the Lua field names)
%   contact         - contact at a prescribed pose, frictionless or rolling
%   wheel           - one wheel with its vertical force given
%   equilibrium     - the static equilibrium under a load Q
%   rigid           - the rigid contact at y, yaw
%   geometry_table  - rigid contact over a range of y
%   conicity        - EN 15302 equivalent conicity of a wheelset or of a Δr table
%   trajectory      - a wheelset followed along time steps
%
% Helpers
%   grid_axes       - the coordinates of a contact area's grid matrices
%   version         - the library's version
