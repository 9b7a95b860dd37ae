"""Shared fixtures of the Python package's tests: profiles and wheelsets of the repository, the build tree."""
import os
import pathlib

import pytest

import wrc

SOURCE = pathlib.Path(os.environ.get("WRC_TEST_SOURCE", pathlib.Path(__file__).resolve().parents[2]))
BUILD = pathlib.Path(os.environ.get("WRC_TEST_BUILD", SOURCE / "build"))


@pytest.fixture(scope="session")
def s1002():
    return wrc.profile.load(str(SOURCE / "profiles/s1002.lua"))


@pytest.fixture(scope="session")
def rail60():
    return wrc.profile.load(str(SOURCE / "profiles/60e1.lua"))


@pytest.fixture(scope="session")
def ws(s1002, rail60):
    return wrc.wheelset(wheel=s1002, rail=rail60)


def run_lua(body, tmp_path):
    """Runs a Lua study through the built wrc executable; its lines 'key=value' (values printed with %.17g) come
    back as a dict of floats: the Lua API's answer to the same call, for the Python results to equal."""
    import subprocess

    script = tmp_path / "reference.lua"
    script.write_text(
        'local function out(k, v) print(("%s=%.17g"):format(k, v)) end\n'
        f'local wheel = wrc.profile.load("{SOURCE}/profiles/s1002.lua")\n'
        f'local rail = wrc.profile.load("{SOURCE}/profiles/60e1.lua")\n'
        "local ws = wrc.wheelset{wheel = wheel, rail = rail}\n" + body)
    exe = BUILD / "wrc"
    done = subprocess.run([str(exe), "run", str(script)], capture_output=True, text=True, cwd=str(SOURCE))
    assert done.returncode == 0, done.stderr
    values = {}
    for line in done.stdout.splitlines():
        if "=" in line:
            k, v = line.split("=", 1)
            values[k] = float(v)
    return values


@pytest.fixture
def lua(tmp_path):
    return lambda body: run_lua(body, tmp_path)
