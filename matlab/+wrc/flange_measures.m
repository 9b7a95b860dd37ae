function m = flange_measures(p, varargin)
%WRC.FLANGE_MEASURES  EN 15313 flange measures of a wheel profile: m.Sh, m.Sd, m.qR (m), m.tip.y, ...
%   m = wrc.flange_measures(p)   or p.flange_measures('tape_offset', 0.070)   (Lua's p:flange_measures)
  m = wrc_mex('flange_measures', wrc.Handle.id_of(p), varargin{:});
end
