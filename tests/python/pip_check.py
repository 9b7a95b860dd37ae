"""`pip wheel .` and `pip install --target` of the package, offline with Debian's setuptools (no build isolation),
then the installed package used from another folder: the module, its profiles and its reader plugins come from the
wheel, and it computes what the build tree's module computes. Run by ctest ("python: pip install")."""
import os
import pathlib
import shutil
import subprocess
import sys

source = pathlib.Path(os.environ["WRC_TEST_SOURCE"])
work = pathlib.Path(os.environ["WRC_TEST_BUILD"]) / "tests" / "tmp" / "pip"
shutil.rmtree(work, ignore_errors=True)
work.mkdir(parents=True)
# The build runs compilers: no sanitizer runtime preloaded into them, no build-tree package on the path.
env = {k: v for k, v in os.environ.items() if k not in ("LD_PRELOAD", "ASAN_OPTIONS", "PYTHONPATH")}
env["WRC_SETUP_BUILD"] = str(work / "setup")
env["PIP_NO_INDEX"] = "1"
# What is checked is the packaging, not the optimiser: the module unoptimised (-O0) compiles in 0.63 of the CPU time
# of Release's -O3 (259 s against 413 s on 2 cores), and the check's one equilibrium runs in a second either way.
env["CMAKE_ARGS"] = "-DCMAKE_CXX_FLAGS_RELEASE=-O0 -DCMAKE_C_FLAGS_RELEASE=-O0"
# Ninja where installed (.ci/deps installs it), through CMake's own variable: it compiles the engine's libraries side
# by side where Make waits for each one's dependencies.
if shutil.which("ninja"):
    env["CMAKE_GENERATOR"] = "Ninja"
subprocess.run([sys.executable, "-m", "pip", "wheel", str(source), "--no-build-isolation", "--no-deps", "-w",
                str(work / "wheel")], check=True, env=env)
wheels = list((work / "wheel").glob("wrc-*.whl"))
assert len(wheels) == 1, wheels
subprocess.run([sys.executable, "-m", "pip", "install", "--no-deps", "--target", str(work / "site"), str(wheels[0])],
               check=True, env=env)

check = r'''
import os, sys, wrc
assert wrc.__file__.startswith(sys.argv[1]), wrc.__file__
w = wrc.profile.load("profiles/s1002.lua")           # from the wheel's share/wrc
assert w.source.startswith(sys.argv[1]), w.source
t = sys.argv[2] + "/w.txt"
w.write(t)                                          # the text reader plugin: from the wheel's lib/wrc/plugins
again = wrc.profile.load(t, kind="wheel")
assert len(again) == len(w)
e = wrc.wheelset(wheel=w, rail=wrc.profile.load("profiles/60e1.lua")).equilibrium(y=3e-3, Q=200e3)
print(repr(e.Y_Q))
'''
env_run = dict(env, PYTHONPATH=str(work / "site"))
out = subprocess.run([sys.executable, "-c", check, str(work / "site"), str(work)], check=True, env=env_run, cwd="/",
                     capture_output=True, text=True).stdout.strip()
# The build tree's module on the same call (this process: PYTHONPATH of the test).
sys.path.insert(0, str(pathlib.Path(os.environ["WRC_TEST_BUILD"]) / "python"))
import wrc  # noqa: E402

here = wrc.wheelset(wheel=wrc.profile.load(str(source / "profiles/s1002.lua")),
                    rail=wrc.profile.load(str(source / "profiles/60e1.lua"))).equilibrium(y=3e-3, Q=200e3)
assert abs(float(out) - here.Y_Q) <= 1e-9 * abs(here.Y_Q), (out, here.Y_Q)
print("pip wheel + install --target: ok, Y/Q", out)
