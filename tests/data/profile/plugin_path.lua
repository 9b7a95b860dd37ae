-- Run with WRC_PLUGIN_PATH = good:duplicate_id:bad_major:no_such_folder test plugin folders (see
-- tests/profile/CMakeLists.txt): the good C plugin reads its files, the others are rejected with reasons.
local check = require "wrc.check"
local H = dofile(os.getenv("WRC_TEST_DATA") .. "/profile/helpers.lua")
local readers, rejected = wrc.profile.readers()
local ids = {}
for _, r in ipairs(readers) do ids[r.id] = r end
check.ok(ids.ctest and ids.text and ids.simpack and ids.miniprof, "built-in readers and the C test plugin are loaded")
local all = table.concat(rejected, "\n")
check.ok(all:find("duplicate reader id 'text'", 1, true), "duplicate id rejected: " .. all)
check.ok(all:find("reader ABI version 99.", 1, true), "wrong ABI major rejected: " .. all)
check.ok(all:find("no_such_folder: plugin folder does not exist", 1, true), "missing folder reported: " .. all)
-- The text reader in use is the built-in one (the first registered keeps the id).
check.ok(ids.text.origin:find("wrc_reader_text", 1, true), "the built-in text reader keeps its id")

local tmp = H.tmpdir() .. "/plugin_path_"
local lines = {}
for i = 0, 20 do lines[#lines + 1] = string.format("%d %.6f", i - 10, -0.01 * (i - 10) ^ 2) end
local ok = H.write(tmp .. "parabola.ctest", table.concat(lines, "\n") .. "\n")
local p = wrc.profile.load(ok)
check.ok(#p == 21 and p.kind == "rail", "the C plugin's points arrive")
check.near(p:interpolate(0.005), -0.01 * 25 * 1e-3, 1e-12, "the C plugin's units (mm) applied")
local bad = H.write(tmp .. "bad.ctest", "1 2\n3 4\nfive 6\n")
check.fails(function() wrc.profile.load(bad) end, "plugin_path_bad.ctest:3: expected two numbers", "C plugin error with line")
print("profile_plugin_path: " .. #rejected .. " rejections reported")
