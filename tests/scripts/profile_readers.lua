-- The reader plugins on sample files written by this test from the analytic S1002 and 60E1 (each format,
-- each orientation convention), read back and compared with the analytic profiles by the distance of
-- every read point to the analytic polyline. Then the sample files the repository carries
-- (tests/data/profile/samples, made by generate_samples.lua there, with the headers of such files in
-- practice): .prw and .whl against the analytic S1002, the canted .prr against the .ban and the .prr
-- canted by its own shift and rotate keys, and all three against the analytic 60E1 canted 1:40 with the
-- origin at the highest point of the canted head.
local check = require "wrc.check"
local H = dofile(os.getenv("WRC_TEST_DATA") .. "/profile/helpers.lua")
local tmp = H.tmpdir() .. "/profile_readers_"

local s1002 = wrc.profile.load("profiles/s1002.lua", {step = 0.2e-3})        -- written to the files
local s1002_fine = wrc.profile.load("profiles/s1002.lua", {step = 0.01e-3})  -- reference polyline
local canted = H.canted_60e1(0.1e-3, 0.030)
local canted_fine = H.canted_60e1(0.01e-3, 0.030)

local function near_profile(p, ref, tol, what, keep)
  local d, wy, wz, n = H.max_distance(p, ref, keep)
  check.ok(n > 100, what .. ": compared " .. n .. " points")
  if d > tol then
    error(string.format("%s: point (%.4f, %.4f) mm is %.5f mm from the reference (tolerance %.3f mm)", what,
                        wy * 1e3, wz * 1e3, d * 1e3, tol * 1e3), 2)
  end
  print(string.format("  %-58s max distance %.6f mm over %d points", what, d * 1e3, n))
  return d
end

-- Simpack wheel written as MBench does it: raw y = -s, mirror.y = 1, inversion = 1, mm.
local prw = H.write_simpack(tmp .. "s1002.prw", s1002, {mirror_y = true, inversion = true, units = 1000})
local w1 = wrc.profile.load(prw)
check.ok(w1.kind == "wheel", "the .prw type = 1 gives a wheel")
check.ok(H.has(w1.transforms, "mirror.y = 1") and H.has(w1.transforms, "inversion = 1") and H.has(w1.transforms, "units.len.f"),
         "the Simpack processing keys are reported: " .. table.concat(w1.transforms, "; "))
near_profile(w1, s1002_fine, 1e-5, "S1002 .prw (mirror.y, inversion)")
check.ok(w1.metadata.comment == "wrc test sample ! not a comment", "a quoted '!' is not a comment")

-- Simpack with a shift and metres as the unit.
local prw_m = H.write_simpack(tmp .. "s1002_m.prw", s1002, {units = 1, shift_y = 0.003, shift_z = -0.001})
near_profile(wrc.profile.load(prw_m), s1002_fine, 1e-5, "S1002 .prw in metres with shift.y/z")

-- MiniProf wheel (X from the flange back, Y toward the flange tip).
local whl = H.write_miniprof(tmp .. "s1002.whl", s1002)
local w2 = wrc.profile.load(whl)
check.ok(w2.kind == "wheel" and H.has(w2.transforms, "toward the flange tip (standard)"), "MiniProf wheel orientation reported")
near_profile(w2, s1002_fine, 1e-5, "S1002 .whl")

-- Plain text and CSV (kind given as an option; the CSV header names the unit).
local txt = H.write_text(tmp .. "s1002.txt", s1002, false)
near_profile(wrc.profile.load(txt, {kind = "wheel"}), s1002_fine, 1e-5, "S1002 .txt")
local csv = H.write_text(tmp .. "s1002.csv", s1002, true)
local w3 = wrc.profile.load(csv, {kind = "wheel"})
check.ok(H.has(w3.transforms, "header 'y_mm' 'z_mm'"), "the CSV header's unit is reported")
near_profile(w3, s1002_fine, 1e-5, "S1002 .csv")

-- The canted 60E1 as .prr (origin at the canted top, gauge side at -y, z down in the file).
local prr = H.write_simpack(tmp .. "uic60.prr", canted)
local r1 = wrc.profile.load(prr)
check.ok(r1.kind == "rail", "the .prr type = 0 gives a rail")
near_profile(r1, canted_fine, 1e-5, "60E1 canted .prr")

-- MiniProf rails: track centre on +X (so mirror_y = true), Y up (standard) or Y down (as MBench).
local ban_up = H.write_miniprof(tmp .. "uic60_up.ban", canted, {x_sign = -1, y_sign = 1})
local ban_down = H.write_miniprof(tmp .. "uic60_down.ban", canted, {x_sign = -1, y_sign = -1})
local r2 = wrc.profile.load(ban_up, {mirror_y = true})
local r3 = wrc.profile.load(ban_down, {mirror_y = true})
check.ok(H.has(r2.transforms, "Y points up (standard)"), "Y up detected: " .. table.concat(r2.transforms, "; "))
check.ok(H.has(r3.transforms, "Y points down (reversed)"), "Y down detected: " .. table.concat(r3.transforms, "; "))
check.ok(H.has(r3.transforms, "mirror_y (option)"), "the mirror option is reported")
check.ok(r3.metadata.marked_points ~= nil, "points marked with '\"' are read and counted")
near_profile(r2, canted_fine, 1e-5, "60E1 canted .ban, Y up")
near_profile(r3, canted_fine, 1e-5, "60E1 canted .ban, Y down")
near_profile(r3, r1, 1e-5, ".ban (Y down) against .prr")
-- The detection can be overridden; forcing the wrong way turns the head upside down (far from 60E1).
local r4 = wrc.profile.load(ban_down, {mirror_y = true, y_axis = "standard"})
check.ok(H.max_distance(r4, canted_fine) > 0.01, "y_axis = standard on a Y-down file gives a different profile")

-- Common options: units given explicitly, shift applied last, crop window, name.
local r5 = wrc.profile.load(prr, {units = "mm", shift = {y = 0.001, z = -0.002}, name = "shifted"})
local y5, z5 = r5:points()
local y1, z1 = r1:points()
check.near(y5[10] - y1[10], 0.001, 1e-12, "shift.y applied")
check.near(z5[10] - z1[10], -0.002, 1e-12, "shift.z applied")
check.ok(r5.name == "shifted" and H.has(r5.transforms, "shift (option)"), "name and shift reported")
local r6 = wrc.profile.load(prr, {crop = {z = {-0.020, 0.001}}})
check.ok(r6:bounds().z_min >= -0.020 and #r6 < #r1, "crop keeps z >= -20 mm")
check.ok(H.has(r6.transforms, "crop (option)"), "crop reported")

-- A reader chosen by id for another extension, and the kind option checked against the file.
local dat = H.write_simpack(tmp .. "s1002_simpack.dat", s1002, {mirror_y = true})
near_profile(wrc.profile.load(dat, {reader = "simpack"}), s1002_fine, 1e-5, "Simpack file named .dat, reader = simpack")
check.fails(function() wrc.profile.load(prw, {kind = "rail"}) end, "holds a wheel profile but the option kind = \"rail\"",
            "kind option contradicting the file")
check.fails(function() wrc.profile.load(txt) end, "pass kind = \"wheel\" or \"rail\"", "text file without kind")
check.fails(function() wrc.profile.load(prw, {colums = "1,2"}) end, "unknown option 'colums' for reader 'simpack'",
            "misspelt reader option")
check.fails(function() wrc.profile.load(tmp .. "missing.prw") end, "no such file", "missing file")
os.remove(tmp .. "s1002.xyz")
check.fails(function() wrc.profile.load(tmp .. "s1002.xyz") end, "no such file", "missing file, unknown extension")
H.write(tmp .. "s1002.xyz", "1 2\n")
check.fails(function() wrc.profile.load(tmp .. "s1002.xyz") end, "no reader for the extension '.xyz'", "unknown extension")

-- The sample files of the repository.
local samples = os.getenv("WRC_TEST_DATA") .. "/profile/samples/"
local mw = wrc.profile.load(samples .. "s1002.prw")
check.ok(mw.kind == "wheel" and mw.name == "s1002", "s1002.prw: a wheel named after the file")
check.ok(H.has(mw.transforms, "5 mirror.y = 1") and H.has(mw.transforms, "6 inversion = 1")
         and H.has(mw.transforms, "units.len.f = +1.000000000000000e+03"),
         "s1002.prw: the processing keys are applied and reported: " .. table.concat(mw.transforms, "; "))
check.ok(mw.metadata.comment == "S1002 h28 e32.5 6.7% ! sampled every 0.5 mm", "s1002.prw: a quoted '!' is kept")
near_profile(mw, s1002_fine, 1e-5, "s1002.prw vs analytic S1002")

local ww = wrc.profile.load(samples .. "s1002.whl")
check.ok(ww.kind == "wheel" and H.has(ww.transforms, "toward the flange tip (standard)"),
         "s1002.whl: Y toward the flange tip detected: " .. table.concat(ww.transforms, "; "))
check.ok(ww.metadata.Sh == "28.00" and ww.metadata.Sd == "32.50" and ww.metadata.ColumnDef == "X,Y,A",
         "s1002.whl: the header keys are kept")
near_profile(ww, s1002_fine, 1e-5, "s1002.whl vs analytic S1002")
near_profile(ww, mw, 1e-6, "s1002.whl vs s1002.prw")

local mr = wrc.profile.load(samples .. "60e1_canted.prr")
local mb = wrc.profile.load(samples .. "60e1_canted.ban", {mirror_y = true})
local mt = wrc.profile.load(samples .. "60e1_rotated.prr")
check.ok(mr.kind == "rail" and mb.kind == "rail" and mt.kind == "rail", "the rail samples are rails")
check.ok(H.has(mb.transforms, "Y points down (reversed)"), "60e1_canted.ban: Y found pointing down")
check.ok(mb.metadata.marked_points == tostring(#mb - 2), "60e1_canted.ban: the points marked with '\"' are counted")
check.ok(H.has(mt.transforms, "2 shift.y") and H.has(mt.transforms, "rotated by -0.0249947936 rad"),
         "60e1_rotated.prr: shift, then rotate in degrees (units.ang.f) by -atan(1/40): " .. table.concat(mt.transforms, "; "))
near_profile(mb, mr, 1e-6, "60e1_canted.ban vs .prr")
near_profile(mr, mb, 1e-6, "60e1_canted.prr vs .ban")
near_profile(mt, mr, 1e-6, "60e1_rotated.prr (uncanted + rotate) vs 60e1_canted.prr")
-- Canted files against the uncanted analytic 60E1 canted 1:40 here (H.canted_60e1; track_paper.lua checks
-- it against the track assembly's own canting).
near_profile(mr, canted_fine, 1e-5, "60e1_canted.prr vs 60E1 canted 1:40")
near_profile(mb, canted_fine, 1e-5, "60e1_canted.ban vs 60E1 canted 1:40")
near_profile(mt, canted_fine, 1e-5, "60e1_rotated.prr vs 60E1 canted 1:40")
