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
