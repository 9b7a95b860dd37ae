-- The Lua front of the wear kernels (wrc.wear, engine/src/lua/wear_binding.cpp): each returns as many values as its
-- documentation says, on polylines whose answers are written out here (a 3-4-5 triangle's arc length, a unit square's
-- area between two lines), and refuses bad input naming the function, the key and what it expected.
local check = require "wrc.check"
local W = wrc.wear

-- Results: counts and values computed by hand.
local arc = W.arc_length{y = {0, 3e-3, 3e-3}, z = {0, 4e-3, 5e-3}}
check.ok(#arc == 3, "arc_length: one arc per point")
check.near(arc[2], 5e-3, 1e-15, "arc_length: the hypotenuse")
check.near(arc[3], 6e-3, 1e-15, "arc_length: plus the last segment")
local cells = W.cells{arc = {0, 2e-3, 6e-3}}
check.near(cells[1] + cells[2] + cells[3], 6e-3, 1e-15, "cells: the cells cover the arc")
check.near(cells[2], 3e-3, 1e-15, "cells: half of each neighbouring segment")
check.ok(select("#", W.project{y = {0, 1e-3}, z = {0, 0}, points_y = {0.5e-3}, points_z = {1e-4}}) == 2,
         "project: arc and distance")
local parc, dist = W.project{y = {0, 1e-3}, z = {0, 0}, points_y = {0.5e-3}, points_z = {1e-4}}
check.near(parc[1], 0.5e-3, 1e-15, "project: the foot's arc")
check.near(dist[1], 1e-4, 1e-15, "project: the distance to the line")
check.ok(select("#", W.deposit{arc = {0, 1e-3, 2e-3}, centre = {1e-3}, width = {1e-3}, area = {1e-9}}) == 2,
         "deposit: depths and the area beyond the ends")
check.ok(select("#", W.normals{y = {0, 1e-3}, z = {0, 0}}) == 2, "normals: ny and nz")
check.ok(select("#", W.move{y = {0, 1e-3}, z = {0, 0}, depth = {0, 0}}) == 2, "move: y and z")
check.ok(select("#", W.smooth{arc = {0, 1e-3}, depth = {0, 0}, length = 1e-3}) == 1, "smooth: the depths")
check.near(W.area_between{y = {0, 1}, z = {0, 0}, y2 = {0, 1}, z2 = {1, 1}}, 1, 1e-15, "area_between: a unit square")

-- Bad input: the function, the key, the expected type and unit.
check.fails(function() W.arc_length{y = {0, 1}} end, "wrc.wear.arc_length: 'z' is required (an array of numbers, m)",
            "a missing array")
check.fails(function() W.deposit{arc = {0, 1}, centre = {1}, width = {1}} end,
            "wrc.wear.deposit: 'area' is required (an array of numbers, m^2)", "a missing area, in m^2")
check.fails(function() W.smooth{arc = {0, 1}, depth = {0, 0}} end, "wrc.wear.smooth: 'length' is required",
            "a missing length")
check.fails(function() W.cells{arc = {0, 1}, ark = 1} end, "wrc.wear.cells: unknown key 'ark'", "an unknown key")
check.fails(function() W.normals{y = {0, 1}, z = {0, 0}, kind = "axle"} end,
            "wrc.wear.normals: 'kind' must be one of \"wheel\", \"rail\", got \"axle\"", "a bad kind")
check.fails(function() W.arc_length{y = {0, 0 / 0}, z = {0, 1}} end, "wrc.wear.arc_length: the 2nd value of 'y' must be finite",
            "a NaN point")
