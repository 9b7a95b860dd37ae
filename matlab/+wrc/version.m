function v = version()
%WRC.VERSION  The version of the wrc library the MEX file is linked with ('0.1.0').
  v = wrc_mex('version');
end
