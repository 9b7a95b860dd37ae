function [ws, wheel, rail] = paper_wheelset()
% The paper's wheelset (S1002 on 60E1, gauge 1435 mm, cant 1:40, r0 = 450 mm), as tests/matlab/reference.lua makes it.
  wheel = wrc.profile_load('profiles/s1002.lua');
  rail = wrc.profile_load('profiles/60e1.lua');
  ws = wrc.wheelset('wheel', wheel, 'rail', rail, 'gauge', 1.435, 'cant', 0.025, 'radius', 0.45);
end
