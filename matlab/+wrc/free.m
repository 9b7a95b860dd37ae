function free(varargin)
%WRC.FREE  Releases wrc objects (profiles, wheelsets, trajectories) now: wrc.free(p, ws, ...). Using one afterwards
%   raises 'wrc:freed'; freeing one twice too. Clearing the last variable that holds an object releases it as well.
  for i = 1:nargin
    wrc_mex('free', wrc.Handle.id_of(varargin{i}));
  end
end
