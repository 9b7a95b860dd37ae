"""wrc.plots: each figure shows the result's data where the conventions put it (docs/design.md, section 2), with
units on its axes, and bad input gets an error that says what is wrong.

The data a figure holds is checked against the results themselves or against geometry outside the plotting code
(a rigid contact point must lie on both drawn profiles), not against pictures.
"""
import math
import os

import numpy as np
import pytest

import wrc
from wrc import plots

from matplotlib.collections import QuadMesh


@pytest.fixture(scope="module")
def paper_ws():
    wheel = wrc.profile.load("profiles/s1002.lua", step=0.1e-3)
    rail = wrc.profile.load("profiles/60e1.lua", step=0.1e-3)
    return wrc.wheelset(wheel=wheel, rail=rail, grid=0.5e-3)


@pytest.fixture(scope="module")
def flange_equilibrium(paper_ws):
    return paper_ws.equilibrium(y=6.5e-3, yaw=0, Q=200e3)


@pytest.fixture(scope="module")
def rolling_patch(paper_ws):
    e = paper_ws.equilibrium(y=3e-3, yaw=0, Q=200e3)
    c = paper_ws.contact(y=3e-3, z=e.z, roll=e.roll, yaw=0, V=100 / 3.6, mu=0.3)
    return max(c.left.patches, key=lambda p: p.normal_force)


def lines(ax, label=None):
    return [l for l in ax.get_lines() if label is None or l.get_label() == label]


def colour_bar_labels(fig):
    """The labels of the figure's colour bars (insets beside their maps)."""
    return [c.get_ylabel() for ax in fig.axes for c in ax.child_axes]


def distance_to_polyline(px, pz, y, z):
    """Shortest distance of the point (px, pz) to the polyline (y, z)."""
    a = np.stack([y[:-1], z[:-1]], 1)
    b = np.stack([y[1:], z[1:]], 1)
    d = b - a
    t = np.clip(((px - a[:, 0]) * d[:, 0] + (pz - a[:, 1]) * d[:, 1]) / np.maximum((d * d).sum(1), 1e-30), 0, 1)
    q = a + t[:, None] * d
    return float(np.min(np.hypot(q[:, 0] - px, q[:, 1] - pz)))


# ---------------------------------------------------------------------------------------------------------------
# The placed profiles (ws.left_wheel, ws.left_rail, ...: the Lua wheelset's fields) that profile_pair draws.

def test_placed_profiles_put_the_gauge_points_where_the_track_parameters_say():
    wheel = wrc.profile.load("profiles/s1002.lua")
    rail = wrc.profile.load("profiles/60e1.lua")
    ws = wrc.wheelset(wheel=wheel, rail=rail, gauge=1.435, gauge_depth=0.014, back_to_back=1.360, radius=0.45)
    for side, sign in (("left", 1), ("right", -1)):
        r, w = getattr(ws, side + "_rail"), getattr(ws, side + "_wheel")
        assert (r.kind, r.frame, w.kind, w.frame) == ("rail", "track", "wheel", "wheelset")
        assert np.all(np.diff(r.y) >= 0) and np.all(np.diff(w.y) >= 0)
        assert r.reversed == (side == "right")
        g = getattr(ws.gauge_points, side)
        assert g.y == pytest.approx(sign * 1.435 / 2, abs=1e-12)
        assert g.z == pytest.approx(getattr(ws.rail_top, side) - 0.014, abs=1e-9)
        assert distance_to_polyline(g.y, g.z, r.y, r.z) < 1e-9
        assert max(r.z) == pytest.approx(getattr(ws.rail_top, side), abs=1e-12)
        # The tape circle: 70 mm outside the flange back, r0 below the axle.
        t = getattr(ws.tape_points, side)
        assert (t.y, t.z) == (pytest.approx(sign * (1.360 / 2 + 0.070)), pytest.approx(-0.45))
        assert distance_to_polyline(t.y, t.z, w.y, w.z) < 1e-9
    ws.close()
    with pytest.raises(wrc.Error, match="Wheelset.left_rail: the wrc.Wheelset was closed"):
        ws.left_rail


# ---------------------------------------------------------------------------------------------------------------
# Profile pair.

def test_profile_pair_rigid_contact_points_lie_on_both_drawn_profiles(paper_ws):
    """The touching points of a rigid contact (track frame, from the engine) lie on the drawn rail and on the drawn
    wheel, which the plot places from the wheelset frame by the result's pose: a wrong roll sign would move the left
    wheel 0.75 m x 2 roll (about 0.5 mm at y = 5 mm) off its point."""
    r = paper_ws.rigid(y=5e-3, Q=200e3)
    assert abs(r.roll) > 2e-4      # the pose matters
    fig = plots.profile_pair(paper_ws, r)
    axes = fig.axes
    assert [a.get_title() for a in axes] == ["left wheel and rail", "right wheel and rail"]
    for ax, side in zip(axes, ("left", "right")):
        rail, = lines(ax, "rail")
        wheel, = lines(ax, "wheel")
        pt = getattr(r, side).contacts[0].point
        for line in (rail, wheel):
            d = distance_to_polyline(pt.y * 1e3, pt.z * 1e3, *line.get_data())
            assert d < 0.01, (side, line.get_label(), d)   # mm
        # Seen in the direction of travel: +y to the left of the page.
        lo, hi = ax.get_xlim()
        assert lo > hi
        assert "mm" in ax.get_xlabel() and "mm" in ax.get_ylabel()


def test_profile_pair_elastic_marks_every_area_with_its_force(paper_ws, flange_equilibrium):
    e = flange_equilibrium
    fig = plots.profile_pair(paper_ws, e)
    for ax, side in zip(fig.axes, ("left", "right")):
        patches = getattr(e, side).patches
        marks = [l for l in ax.get_lines() if l.get_marker() == "o"]
        assert len(marks) == len(patches)
        for m, p in zip(marks, patches):
            assert m.get_xdata()[0] == pytest.approx(p.point.y * 1e3, abs=1e-9)
            assert m.get_ydata()[0] == pytest.approx(p.point.z * 1e3, abs=1e-9)
        texts = [t.get_text() for t in ax.texts]
        for p in patches:
            assert any("%.1f kN" % (p.normal_force / 1e3) in t for t in texts), texts
        assert ("lifted: no contact" in texts) == getattr(e, side).lifted
    # Flange contact on the left wheel: its normal (from the rail into the wheel) points toward -y.
    left_flange = max(e.left.patches, key=lambda p: p.angle)
    assert left_flange.angle > math.radians(30) and left_flange.normal.y < 0


def test_profile_pair_pose_override_and_bad_input(paper_ws):
    fig = plots.profile_pair(paper_ws, pose={"y": 2e-3, "roll": 1e-3}, sides="left")
    assert len(fig.axes) == 1
    assert "y = 2.00 mm" in fig._suptitle.get_text()
    with pytest.raises(ValueError, match="pose: unknown key 'rol'"):
        plots.profile_pair(paper_ws, pose={"rol": 1e-3})
    with pytest.raises(ValueError, match=r"pose\['y'\] = nan"):
        plots.profile_pair(paper_ws, pose={"y": float("nan")})
    with pytest.raises(ValueError, match="sides: 'middle'"):
        plots.profile_pair(paper_ws, sides=("left", "middle"))
    with pytest.raises(ValueError, match="no field 'left_wheel'"):
        plots.profile_pair(object())


# ---------------------------------------------------------------------------------------------------------------
# Maps.

def test_pressure_map_shows_the_grid_in_mpa_and_mm(flange_equilibrium):
    p = max(flange_equilibrium.left.patches, key=lambda p: p.normal_force)
    fig = plots.pressure_map(p)
    ax = fig.axes[0]
    mesh, = [c for c in ax.collections if isinstance(c, QuadMesh)]
    shown = np.ma.filled(mesh.get_array(), np.nan).reshape(p.pressure.shape)
    expected = np.where(p.pressure > 0, p.pressure / 1e6, np.nan)
    np.testing.assert_array_equal(np.isnan(shown), np.isnan(expected))
    np.testing.assert_allclose(shown[~np.isnan(shown)], expected[~np.isnan(expected)], rtol=1e-12)
    assert np.nanmax(shown) == pytest.approx(p.pmax / 1e6, rel=1e-12)
    # The element edges span the grid, in mm.
    g = p.grid
    xlo, xhi = ax.get_xlim()
    assert xlo == pytest.approx((g.x0 - g.dx / 2) * 1e3) and xhi == pytest.approx((g.x0 + (g.nx - 0.5) * g.dx) * 1e3)
    assert colour_bar_labels(fig) == ["normal pressure p (MPa)"]
    assert "mm" in ax.get_xlabel() and "mm" in ax.get_ylabel()
    assert "%.1f kN" % (p.normal_force / 1e3) in ax.get_title()


def test_traction_map_shows_adhesion_and_slip_and_rejects_a_frictionless_patch(rolling_patch, flange_equilibrium):
    p = rolling_patch
    fig = plots.traction_map(p)
    ax1 = fig.axes[0]
    mesh = [c for c in ax1.collections if isinstance(c, QuadMesh)][0]
    state = np.asarray(mesh.get_array()).reshape(p.adhesion_map.shape)
    np.testing.assert_array_equal(state, p.adhesion_map)
    assert set(np.unique(state)) <= {0, 1, 2} and (state == 1).any() and (state == 2).any()
    assert [t.get_text() for t in ax1.get_legend().get_texts()] == ["adhesion", "slip"]
    assert colour_bar_labels(fig) == ["|tangential traction| (MPa)", "|slip velocity| (mm/s)"]
    frictionless = flange_equilibrium.left.patches[0]
    with pytest.raises(ValueError, match="rolling keys"):
        plots.traction_map(frictionless)


def test_pressure_map_without_grids_says_so(paper_ws):
    c = paper_ws.contact(y=0, z=-0.05e-3, roll=0, yaw=0, grids=False)
    with pytest.raises(ValueError, match="grids=True"):
        plots.pressure_map(c.left.patches[0])


# ---------------------------------------------------------------------------------------------------------------
# Creep curves.

def test_creep_curves_plot_minus_force_over_mu_n_against_the_areas_creepage(paper_ws):
    xis = [0, 0.5e-3, 1e-3, 2e-3]
    curves = {m: [paper_ws.wheel(side="left", y=0, Fz=100e3, creepage={"xi": xi}, mu=0.3, method=m,
                           grids=False).patches[0] for xi in xis] for m in ("exact", "fastsim")}
    fig = plots.creep_curves(curves, linear=5e7)
    ax = fig.axes[0]
    for m in ("exact", "fastsim"):
        line, = lines(ax, m)
        x, y = line.get_data()
        np.testing.assert_allclose(x, np.array(xis) * 1e3)       # permille
        np.testing.assert_allclose(y, [-p.Fx / (0.3 * p.normal_force) for p in curves[m]], rtol=1e-12)
        assert y[-1] > 0      # braking: Fx < 0 plotted positive
    lin, = lines(ax, "linear theory")
    (x0, x1), (y0, y1) = lin.get_data()
    N = curves["exact"][0].normal_force
    assert (y1 - y0) / ((x1 - x0) * 1e-3) == pytest.approx(5e7 / (0.3 * N))
    assert "ξ" in ax.get_xlabel() and "μ N" in ax.get_ylabel()
    fig = plots.creep_curves(curves, normalise=False)
    line, = lines(fig.axes[0], "exact")
    np.testing.assert_allclose(line.get_ydata(), [-p.Fx / 1e3 for p in curves["exact"]])
    assert "kN" in fig.axes[0].get_ylabel()


def test_creep_curves_bad_input(paper_ws, flange_equilibrium):
    with pytest.raises(TypeError, match="expected a non-empty dict"):
        plots.creep_curves([1, 2])
    with pytest.raises(ValueError, match="force = 'Fz'"):
        plots.creep_curves({"a": [1]}, force="Fz")
    with pytest.raises(ValueError, match="no creepage"):
        plots.creep_curves({"frictionless": flange_equilibrium.left.patches})
    with pytest.raises(TypeError, match=r"curves\['x'\] is str"):
        plots.creep_curves({"x": "abc"})


# ---------------------------------------------------------------------------------------------------------------
# Conicity and Y/Q.

def test_conicity_draws_the_dr_table_and_tan_gamma(paper_ws):
    d = paper_ws.conicity(yhat=[1e-3, 2e-3, 3e-3])
    tan = d.tan_gamma
    fig = plots.conicity(d, labels=["S1002/60E1"])
    ax1, ax2 = fig.axes
    dr_line = lines(ax1, "S1002/60E1")[0]
    np.testing.assert_allclose(dr_line.get_xdata(), np.asarray(d.dr.y) * 1e3)
    np.testing.assert_allclose(dr_line.get_ydata(), np.asarray(d.dr.dr) * 1e3)
    tan_line = lines(ax2)[0]
    np.testing.assert_allclose(tan_line.get_xdata(), [1, 2, 3])
    np.testing.assert_allclose(tan_line.get_ydata(), tan)
    assert "mm" in ax1.get_xlabel() and "mm" in ax1.get_ylabel() and "mm" in ax2.get_xlabel()
    assert "tan γe" in ax2.get_ylabel()
    # Δr = r_left - r_right rises with y (+ toward the left rail: the left wheel rolls on a larger radius).
    y, dr = np.asarray(d.dr.y), np.asarray(d.dr.dr)
    assert dr[y > 2e-3].min() > 0 > dr[y < -2e-3].max()


def test_conicity_bad_input():
    with pytest.raises(ValueError, match="results is empty"):
        plots.conicity([])
    with pytest.raises(ValueError, match="neither a conicity result"):
        plots.conicity({"a": 1})
    with pytest.raises(ValueError, match="expected a list of 2 label"):
        plots.conicity([{"yhat": [1e-3], "tan_gamma": [0.1]}] * 2, labels=["one"])
    with pytest.raises(ValueError, match="differ in length"):
        plots.conicity({"yhat": [1e-3, 2e-3], "tan_gamma": [0.1]})


def test_sweep_yq_one_line_per_yaw_with_the_rigid_reference(paper_ws):
    s = paper_ws.sweep(y={"from": -7e-3, "to": 7e-3, "step": 1e-3}, yaw=[0, math.radians(1)], Q=200e3, rigid=True,
                 grids=False)
    fig = plots.sweep_yq(s, limit=0.8)
    ax = fig.axes[0]
    for yaw in (0, math.radians(1)):
        cases = sorted((c for c in s.rows if c.yaw == yaw), key=lambda c: c.y)
        name = "yaw %.3g°" % math.degrees(yaw)
        el, = lines(ax, name + ", elastic")
        rg, = lines(ax, name + ", rigid")
        np.testing.assert_allclose(el.get_xdata(), [c.y * 1e3 for c in cases])
        np.testing.assert_allclose(el.get_ydata(), [c.Y_Q if c.converged else np.nan for c in cases])
        np.testing.assert_allclose(rg.get_ydata(), [c.rigid.Y_Q for c in cases])
    # Y > 0 pushes toward the left rail: Y/Q rises with y.
    el, = lines(ax, "yaw 0°, elastic")
    assert el.get_ydata()[-1] > 0.5 > -0.5 > el.get_ydata()[0]
    assert "mm" in ax.get_xlabel() and "Y/Q" in ax.get_ylabel()
    with pytest.raises(ValueError, match="limit = -1"):
        plots.sweep_yq(s, limit=-1)
    with pytest.raises(TypeError, match="expected a sweep's result"):
        plots.sweep_yq(42)


def test_sweep_yq_from_a_dataframe():
    pd = pytest.importorskip("pandas")
    df = pd.DataFrame({"yaw_deg": [0, 0, 0], "y_mm": [1.0, -1.0, 0.0], "Y_Q": [0.02, -0.02, 0.0],
                       "converged": [1, 1, 0]})
    fig = plots.sweep_yq(df)
    line, = lines(fig.axes[0], "yaw 0°, elastic")
    np.testing.assert_allclose(line.get_xdata(), [-1, 0, 1])
    np.testing.assert_allclose(line.get_ydata(), [-0.02, np.nan, 0.02])
    with pytest.raises(ValueError, match=r"none of the columns 'y \[m\]', 'y_mm'"):
        plots.sweep_yq(pd.DataFrame({"Y_Q": [0.1]}))


# ---------------------------------------------------------------------------------------------------------------
# Saving.

def test_path_writes_the_picture_whole_or_not_at_all(tmp_path, flange_equilibrium):
    p = flange_equilibrium.left.patches[0]
    out = tmp_path / "pressure.png"
    fig = plots.pressure_map(p, path=out)
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert fig.axes
    assert sorted(os.listdir(tmp_path)) == ["pressure.png"]      # no temporary file left
    with pytest.raises(FileNotFoundError, match="does not exist"):
        plots.pressure_map(p, path=tmp_path / "missing" / "p.png")
    with pytest.raises(TypeError, match="path is int"):
        plots.pressure_map(p, path=3)
    # A format matplotlib does not know: an error, and no file.
    with pytest.raises(ValueError):
        plots.pressure_map(p, path=tmp_path / "p.unknownformat")
    assert sorted(os.listdir(tmp_path)) == ["pressure.png"]
