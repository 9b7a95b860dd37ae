function ws = wheelset(varargin)
%WRC.WHEELSET  A wheelset from one wheel and one rail profile (the right side their mirror image), or from four.
%   ws = wrc.wheelset('wheel', w, 'rail', r)
%   ws = wrc.wheelset('left_wheel', wl, 'right_wheel', wr, 'left_rail', rl, 'right_rail', rr, 'gauge', 1.435)
%   Options: the keys of Lua's wrc.wheelset (radius, back_to_back, tape_offset, gauge, gauge_depth, gauge_point,
%   cant, E, nu, grid, margin, max_elements, tolerance, merge_tolerance, merge_angle, solver, surface, strategy,
%   strategy_options.*, check_strategy, check_setup), with the engine's defaults (docs/reference/lua-api.md).
%   The profiles are copied. Returns a wrc.WheelsetHandle.
  args = wrc.Handle.unwrap(varargin);
  ws = wrc.WheelsetHandle(wrc_mex('wheelset', args{:}));
end
