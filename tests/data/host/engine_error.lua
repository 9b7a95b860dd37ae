-- an engine error (misspelt option) on line 2
local ws = wrc.wheelset{raduis = 0.45}
