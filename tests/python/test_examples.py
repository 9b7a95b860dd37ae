"""The Python examples: the package's and the ctypes one print the same study; the ctypes one, without its library,
stops with a message saying what to do (not a raw OSError)."""
import os
import subprocess
import sys

from conftest import BUILD, SOURCE


def run(script, *args, **env):
    return subprocess.run([sys.executable, str(SOURCE / "examples/python" / script), *args], capture_output=True,
                          text=True, cwd=str(SOURCE), env=dict(os.environ, **env))


def test_package_example_prints_what_the_c_api_example_prints():
    package = run("paper_equilibrium_package.py")
    assert package.returncode == 0, package.stderr
    c_api = run("paper_equilibrium.py", str(BUILD / "libwrc.so"))
    assert c_api.returncode == 0, c_api.stderr
    assert "left patch 1: N = " in package.stdout
    assert package.stdout == c_api.stdout


def test_ctypes_example_without_its_library():
    done = run("paper_equilibrium.py", "/nonexistent/libwrc.so.0")
    assert done.returncode == 1
    assert "cannot load the C library of wrc '/nonexistent/libwrc.so.0'" in done.stderr
    assert "WRC_LIBRARY" in done.stderr and "Traceback" not in done.stderr
