"""wrc.profile and wrc.Profile: loading, attributes, points as numpy, EN 15313 flange measures, writing, errors."""
import math
import os
import warnings

import numpy as np
import pytest

import wrc

from conftest import SOURCE


def test_load_attributes(s1002):
    assert s1002.kind == "wheel" and s1002.name == "S1002"
    y, z = s1002.points()
    assert y.dtype == np.float64 and y.shape == (len(s1002),) and z.shape == y.shape
    assert np.all(np.diff(y) > 0)
    # The definition samples every 0.1 mm in y from -70 to 60 mm (1301 points).
    assert len(s1002) == 1301 and y[0] == pytest.approx(-0.070) and y[-1] == pytest.approx(0.060)
    assert np.allclose(np.diff(y), 1e-4, rtol=1e-6)
    assert np.array_equal(s1002.y, y) and np.array_equal(s1002.z, z)
    assert "S1002" in repr(s1002)
    assert isinstance(s1002.transforms, list) and isinstance(s1002.metadata, dict)


def test_load_options_and_pathlike(tmp_path):
    p = wrc.profile.load(SOURCE / "profiles/s1002.lua", step=1e-3)  # a pathlib.Path, a definition's option
    assert len(p) == 131  # the same count the install check of the Lua host asserts


def test_points():
    p = wrc.profile.points(kind="rail", y=[-0.03, 0.0, 0.03], z=[-0.01, 0.0, -0.01], name="roof")
    assert p.kind == "rail" and p.name == "roof" and len(p) == 3
    np.testing.assert_array_equal(p.z, [-0.01, 0.0, -0.01])
    assert wrc.profile.points(kind="wheel", y=np.array([0.0, 0.01, 0.02]), z=(0, 0, 0)).name == "wheel"


def test_flange_measures_s1002(s1002):
    m = s1002.flange_measures()
    # EN 13715 S1002, new: flange height 28 mm, flange thickness 32.5 mm, qR 10.8 mm (EN 15313's nominal values).
    assert m.Sh == pytest.approx(0.028, abs=1e-5)
    assert m.Sd == pytest.approx(0.0325, abs=1e-5)
    assert m.qR == pytest.approx(0.0108, abs=0.1e-3)
    assert m.units["Sh"] == "m"
    assert s1002.flange_measures(tape_offset=0.070).Sh == m.Sh


def test_flange_measures_equal_lua(s1002, lua):
    ref = lua("local m = wheel:flange_measures{}\nout('Sh', m.Sh) out('Sd', m.Sd) out('qR', m.qR)\n")
    m = s1002.flange_measures()
    assert (m.Sh, m.Sd, m.qR) == (ref["Sh"], ref["Sd"], ref["qR"])


def test_write_and_read_back(s1002, tmp_path):
    path = tmp_path / "w.csv"
    assert s1002.write(path) == "csv"
    again = wrc.profile.load(path, kind="wheel")
    assert len(again) == len(s1002)
    np.testing.assert_allclose(again.y, s1002.y, atol=1e-9)
    np.testing.assert_allclose(again.z, s1002.z, atol=1e-9)


def test_load_warnings_are_python_warnings(s1002, tmp_path):
    """A loaded profile's warnings are wrc.ProfileWarning (a notebook shows them; stderr it does not): S1002 with
    2 um of scatter added to z, written in mm, warns of the scatter and names the remedy; smoothed it does not; a
    filter can make the warning an error."""
    y, z = s1002.points()
    z = z + 2e-6 * np.random.default_rng(1).standard_normal(len(z))
    path = tmp_path / "scattered.txt"
    np.savetxt(path, np.column_stack([y, z]) * 1e3, fmt="%.6f")
    with pytest.warns(wrc.ProfileWarning, match="smooth = 0.5e-3") as record:
        p = wrc.profile.load(path, kind="wheel")
    assert [str(w.message) for w in record] == p.warnings and len(p.warnings) == 1
    assert record[0].filename == __file__  # attributed to the caller's line
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert wrc.profile.load(path, kind="wheel", smooth=0.5e-3).warnings == []
        with pytest.raises(wrc.ProfileWarning, match="scatter"):
            wrc.profile.load(path, kind="wheel")


def test_points_scatter_is_warned_of_too(s1002):
    """Points given as arrays (wrc.profile.points, the polyline through them) are checked for scatter as a loaded
    file's: S1002 with 2 um of scatter added to z warns, naming points' own remedy (smooth=), which removes it; the
    clean points do not warn."""
    y, z = s1002.points()
    noisy = z + 2e-6 * np.random.default_rng(1).standard_normal(len(z))
    with pytest.warns(wrc.ProfileWarning, match="Make it with a smoothing length, smooth = 0.5e-3") as record:
        p = wrc.profile.points(kind="wheel", y=y, z=noisy)
    assert len(record) == 1 and record[0].filename == __file__ and p.warnings == [str(record[0].message)]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        smoothed = wrc.profile.points(kind="wheel", y=y, z=noisy, smooth=0.5e-3)
        assert smoothed.warnings == [] and smoothed.smooth == 0.5e-3
        assert wrc.profile.points(kind="wheel", y=y, z=z).warnings == []
    with pytest.raises(wrc.Error, match="smooth = -1"):
        wrc.profile.points(kind="wheel", y=y, z=z, smooth=-1)


def test_load_errors(tmp_path):
    with pytest.raises(wrc.ProfileError, match="nope.txt"):
        wrc.profile.load(str(tmp_path / "nope.txt"))
    with pytest.raises(TypeError, match="path"):
        wrc.profile.load(42)
    with pytest.raises(wrc.Error, match="did you mean 'step'"):
        wrc.profile.load(str(SOURCE / "profiles/s1002.lua"), stpe=1e-3)
    with pytest.raises(wrc.OptionError, match="finite"):
        wrc.profile.points(kind="wheel", y=[0.0, math.nan, 0.02], z=[0.0, 0.0, 0.0])
    with pytest.raises(wrc.OptionError, match="kind"):
        wrc.profile.points(kind="axle", y=[0.0, 0.01, 0.02], z=[0.0, 0.0, 0.0])
    with pytest.raises(TypeError, match="'y'"):
        wrc.profile.points(kind="wheel", y={1, 2, 3}, z=[0.0, 0.0, 0.0])


def test_close_and_context_manager(tmp_path):
    p = wrc.profile.load(str(SOURCE / "profiles/60e1.lua"))
    p.close()
    for use in (lambda: p.name, lambda: p.points(), lambda: len(p), lambda: p.flange_measures(),
                lambda: p.write(str(tmp_path / "x.csv"))):
        with pytest.raises(wrc.Error, match="closed"):
            use()
    assert "closed" in repr(p)
    with wrc.profile.load(str(SOURCE / "profiles/s1002.lua")) as w:
        assert w.kind == "wheel"
    with pytest.raises(wrc.Error, match="closed"):
        w.points()
    with pytest.raises(wrc.Error, match="closed"):
        wrc.wheelset(wheel=w, rail=wrc.profile.load(str(SOURCE / "profiles/60e1.lua")))
    assert not os.path.exists(tmp_path / "x.csv")


def test_geometry_of_a_circular_arc():
    # A rail head that is an arc of radius R: curvature 1/R, arc length R * angle, bounds from the drawing.
    R = 0.3
    y = np.arange(-0.02, 0.02 + 1e-9, 0.1e-3)
    p = wrc.profile.points(kind="rail", y=y, z=np.sqrt(R * R - y * y) - R)
    for at in (0.0, 0.01):
        k, radius = p.curvature(at)
        assert k == pytest.approx(1 / R, rel=1e-6) and radius == pytest.approx(R, rel=1e-6)
    assert p.arc_length() == pytest.approx(2 * R * math.asin(0.02 / R), rel=1e-6)
    b = p.bounds()
    assert b["z_max"] == 0 and b["z_min"] == pytest.approx(math.sqrt(R * R - 0.02 ** 2) - R, abs=1e-15)
    moved = p.transform(shift={"y": 1e-3})
    np.testing.assert_allclose(moved.y, p.y + 1e-3, atol=1e-15)
    with pytest.raises(wrc.OptionError, match="did you mean 'shift'"):
        p.transform(shfit={"y": 1e-3})
