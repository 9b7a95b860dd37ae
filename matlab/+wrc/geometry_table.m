function t = geometry_table(ws, varargin)
%WRC.GEOMETRY_TABLE  A rigid contact geometry table on worker threads (Lua's ws:geometry_table).
%   t = wrc.geometry_table(ws, 'y', struct('from', -8e-3, 'to', 8e-3, 'step', 0.1e-3), 'roll', 'fixed')
%   Keys: y.from, y.to, y.step (or y = [a b c]), yaw, roll, Q, two_point_tolerance, threads, jump_threshold, csv,
%   file, progress. t.rows is a struct array (t.rows(k).rolling_radius_difference), t.jumps another.
  t = wrc_mex('geometry_table', wrc.Handle.id_of(ws), varargin{:});
end
