classdef (Abstract) Handle < handle
%WRC.HANDLE  A profile, wheelset or trajectory of the wrc engine, owned by MATLAB.
%   The object is released when the last variable holding it is cleared, or at once by wrc.free(obj) (or
%   obj.free()). A freed object used again raises the error 'wrc:freed'.
  properties (SetAccess = protected)
    id  % the MEX file's key of the object (uint64): never an address
  end
  methods
    function free(obj)
      %FREE  Releases the object now; using it afterwards raises 'wrc:freed'.
      wrc_mex('free', obj.id);
    end
    function delete(obj)
      % The destructor: quiet for an object freed already (wrc.free, or an earlier delete).
      if ~isempty(obj.id)
        wrc_mex('free', obj.id, true);
      end
    end
    function k = kind(obj)
      %KIND  'profile', 'wheelset', 'trajectory', or 'freed'.
      k = wrc_mex('kind', obj.id);
    end
  end
  methods (Static, Hidden)
    function args = unwrap(args)
      % The wrc objects among name/value arguments (and the fields of a struct argument) as the MEX file's ids.
      for i = 1:numel(args)
        if isa(args{i}, 'wrc.Handle')
          args{i} = args{i}.id;
        elseif isstruct(args{i}) && isscalar(args{i})
          f = fieldnames(args{i});
          for k = 1:numel(f)
            if isa(args{i}.(f{k}), 'wrc.Handle')
              args{i}.(f{k}) = args{i}.(f{k}).id;
            end
          end
        end
      end
    end
    function id = id_of(x)
      % The id of a wrc object; anything else goes on as it is, for the MEX file to refuse with a message.
      if isa(x, 'wrc.Handle')
        id = x.id;
      else
        id = x;
      end
    end
  end
end
