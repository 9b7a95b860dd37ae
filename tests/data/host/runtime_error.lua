-- a runtime error on line 3
local t = {}
local x = t.missing + 1
print(x)
