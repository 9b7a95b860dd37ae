"""wrc.wheelset and its calls against independent references: Hertz for a contact, the Lua API (the built wrc
executable) for the same calls, symmetry, Coulomb's limit for full slip, the cone slope for conicity."""
import math
import warnings

import numpy as np
import pandas as pd
import pytest

import wrc

E, NU = 2.1e11, 0.3


def hertz_pair(R, r0=0.45, grid=0.25e-3):
    """A cylindrical wheel (radius r0) on a rail crowned with the transverse radius R, no cant: Hertz's pair."""
    y = np.arange(-0.070, 0.0605, 1e-3)
    wheel = wrc.profile.points(kind="wheel", y=y, z=0 * y, name="cylinder")
    yr = np.arange(-0.025, 0.025 + 1e-9, 0.02e-3)
    rail = wrc.profile.points(kind="rail", y=yr, z=np.sqrt(R * R - yr * yr) - R, name="crown")
    gauge_depth = 0.2e-3
    yg = math.sqrt(R * R - (R - gauge_depth) ** 2)  # the gauge point on the crown's gauge side
    return wrc.wheelset(wheel=wheel, rail=rail, radius=r0, cant=0, gauge_depth=gauge_depth, gauge=2 * (0.75 - yg),
                        grid=grid, E=E, nu=NU, strategy=["coarse", "topology"])


def test_contact_is_hertz_for_a_circular_contact():
    # R = r0: h = delta - (x^2 + y^2) / (2 r0), a sphere of radius r0 on a plane; E* = E / (2 (1 - nu^2)).
    r0, delta = 0.45, 50e-6
    c = hertz_pair(R=r0, r0=r0).contact(z=-delta, grids=True)
    Es = E / (2 * (1 - NU * NU))
    F = 4 / 3 * Es * math.sqrt(r0) * delta ** 1.5
    a = math.sqrt(r0 * delta)
    p0 = 3 * F / (2 * math.pi * a * a)
    for side in (c.left, c.right):
        assert len(side.patches) == 1
        p = side.patches[0]
        assert p.normal_force == pytest.approx(F, rel=2e-3)
        assert p.pmax == pytest.approx(p0, rel=2e-3)
        assert p.area == pytest.approx(math.pi * a * a, rel=0.03)
    assert c.force.z == pytest.approx(2 * F, rel=2e-3)


def test_a_contact_too_narrow_for_its_grid_warns_once():
    """The sphere on a plane of the test above on grids of 5 and 2.5 mm (the contact 9.5 mm across): on the first it
    spans 3 elements each way, its pmax is 13 % above Hertz's p0, and wrc.ResolutionWarning says so once for the
    wheelset (two calls and a trajectory's step), naming a grid that resolves it; on the second it spans 5, pmax is
    within the 3.3 % such a span allows, and nothing is said."""
    r0, delta = 0.45, 50e-6
    Es = E / (2 * (1 - NU * NU))
    F = 4 / 3 * Es * math.sqrt(r0) * delta ** 1.5
    p0 = 3 * F / (2 * math.pi * r0 * delta)
    with pytest.warns(wrc.ResolutionWarning, match=r"spans only 3 x 3 elements .* grid = 1\.2e-3 or finer") as record:
        ws = hertz_pair(R=r0, r0=r0, grid=5e-3)
        first, again = ws.contact(z=-delta), ws.contact(z=-delta)
        ws.trajectory().contact(z=-delta)
    assert len(record) == 1 and record[0].filename == __file__
    for c in (first, again):
        p = c.left.patches[0]
        assert not p.resolved and (p.span.x, p.span.y) == (3, 3)
        assert p.pmax / p0 - 1 > 0.1
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        p = hertz_pair(R=r0, r0=r0, grid=2.5e-3).contact(z=-delta).left.patches[0]
    assert p.resolved and min(p.span.x, p.span.y) >= 4
    assert p.pmax == pytest.approx(p0, rel=0.033)


def test_a_grid_finer_than_the_step_refines_the_default_step():
    # S1002 on 60E1 as their splines, the left wheel at the flange root (1 kN) on a 0.05 mm grid: the default step
    # follows the grid (docs/guide/normal.md), within 0.5 % of profiles resampled 4x finer than the grid in pmax;
    # the old default, step = 0.1 mm given (and kept), resolves the cones' kinks and is 2 % or more above.
    w = wrc.profile.load("profiles/s1002.lua", smooth=0)
    r = wrc.profile.load("profiles/60e1.lua", smooth=0)

    def pmax(**strategy):
        ws = wrc.wheelset(wheel=w, rail=r, grid=0.05e-3, **strategy)
        return ws.wheel(side="left", y=7e-3, Fz=1e3).patches[0].pmax

    default, fine = pmax(), pmax(strategy_options={"step": 0.0125e-3})
    assert default == pytest.approx(fine, rel=5e-3)
    assert pmax(strategy_options={"step": 0.1e-3}) > 1.02 * fine


def test_pressure_grid_is_ny_by_nx_with_its_coordinates():
    # R = 0.3 m < r0: the ellipse is longer along the track (x) than across (y), by about (B/A)^(2/3) = 1.31.
    c = hertz_pair(R=0.30).contact(z=-50e-6, grids=True)
    p = c.left.patches[0]
    g = p.grid
    assert p.pressure.shape == (g.ny, g.nx) and p.h.shape == (g.ny, g.nx) and p.pressure.dtype == np.float64
    assert g.x.shape == (g.nx,) and g.y.shape == (g.ny,)
    loaded = p.pressure > 0
    along_x = np.ptp(g.x[np.any(loaded, axis=0)])
    along_y = np.ptp(g.y[np.any(loaded, axis=1)])
    assert 1.15 < along_x / along_y < 1.5
    # The pressure integrates to the area's force, and its peak sits at the centre of pressure.
    assert p.pressure.sum() * g.dx * g.dy == pytest.approx(p.pressure_integral, rel=1e-9)
    j, i = np.unravel_index(np.argmax(p.pressure), p.pressure.shape)
    assert abs(g.x[i]) <= g.dx and p.elements == int(loaded.sum())


def test_equilibrium_and_rigid_equal_lua(ws, lua):
    ref = lua("local e = ws:equilibrium{y = 3e-3, yaw = 2e-3, Q = 200e3}\n"
              "out('z', e.z) out('roll', e.roll) out('Y', e.Y) out('pmax', e.left.patches[1].pmax)\n"
              "local r = ws:rigid{y = 3e-3, Q = 200e3}\n"
              "out('rz', r.z) out('rdr', r.rolling_radius_difference) out('rY', r.Y)\n"
              "local c = ws:contact{y = 3e-3, z = e.z, roll = e.roll, yaw = 2e-3}\n"
              "out('cFz', c.force.z) out('cFy', c.force.y)\n")
    e = ws.equilibrium(y=3e-3, yaw=2e-3, Q=200e3)
    assert (e.z, e.roll, e.Y, e.left.patches[0].pmax) == (ref["z"], ref["roll"], ref["Y"], ref["pmax"])
    r = ws.rigid(y=3e-3, Q=200e3)
    assert (r.z, r.rolling_radius_difference, r.Y) == (ref["rz"], ref["rdr"], ref["rY"])
    c = ws.contact(y=3e-3, z=e.z, roll=e.roll, yaw=2e-3)
    assert (c.force.z, c.force.y) == (ref["cFz"], ref["cFy"])
    # At equilibrium the contact carries the load: Fz = Q.
    assert c.force.z == pytest.approx(200e3, rel=1e-6)


def test_equilibrium_centred_is_symmetric(ws):
    e = ws.equilibrium(y=0, Q=200e3)
    assert e.converged and abs(e.Y) < 1e-6 * 200e3 and abs(e.roll) < 1e-9
    assert e.left.force.z == pytest.approx(e.right.force.z, rel=1e-6)
    assert e.keys() and "Y_Q" in e.keys() and isinstance(e.to_dict()["left"], dict)


def test_wheel_carries_its_load(ws):
    w = ws.wheel(side="left", y=2e-3, Fz=100e3)
    assert w.converged
    assert w.force.z == pytest.approx(100e3, rel=1e-6)
    assert w.patches[0].pmax > 0 and w.patches[0].units["pmax"] == "Pa"


def test_not_converged_raises_or_returns(rail60):
    # A wheel without flange (S1002 from the tape circle on) at y = 100 mm: no wheel can touch, no equilibrium (the
    # case of tests/scripts/equilibrium_failure.lua).
    flangeless = wrc.profile.load("profiles/s1002.lua", **{"from": 0})
    bare = wrc.wheelset(wheel=flangeless, rail=rail60, grid=2e-3)
    with pytest.raises(wrc.NotConverged, match="no equilibrium found at y = 100.0000 mm.*on_failure") as err:
        bare.equilibrium(y=0.1, Q=200e3, max_iterations=3)
    assert err.value.result is not None and err.value.result.converged is False
    assert len(err.value.result.left.patches) == 0
    r = bare.equilibrium(y=0.1, Q=200e3, max_iterations=3, on_failure="return")
    assert r.converged is False and r.error and math.isfinite(r.z)
    # One wheel stopped after one contact evaluation.
    ws = wrc.wheelset(wheel=wrc.profile.load("profiles/s1002.lua"), rail=rail60)
    with pytest.raises(wrc.NotConverged, match="max_evaluations") as err:
        ws.wheel(side="left", y=2e-3, Fz=100e3, max_evaluations=1)
    assert err.value.result.converged is False
    assert ws.wheel(side="left", y=2e-3, Fz=100e3, max_evaluations=1, on_failure="return").converged is False


def test_rolling_full_slip_is_coulomb(ws):
    # A creepage far past saturation: the whole area slips and the creep force is mu times the normal force.
    e = ws.equilibrium(y=0, Q=200e3)
    c = ws.contact(y=0, z=e.z, roll=e.roll, V=20, creepage={"xi": 0.05, "eta": 0, "phi": 0}, mu=0.3)
    for side in (c.left, c.right):
        N = sum(p.normal_force for p in side.patches)
        assert math.hypot(side.creep_force.x, side.creep_force.y) == pytest.approx(0.3 * N, rel=5e-3)
        assert side.creep_force.x < 0  # opposes the wheel's slip (xi > 0)


def test_rolling_equals_lua(ws, lua):
    ref = lua("local c = ws:contact{y = 2e-3, z = -40e-6, V = 30, creepage = {xi = 1e-3, eta = 0.5e-3, phi = 0},"
              " mu = 0.3, method = 'fastsim'}\nout('Fx', c.left.creep_force.x) out('Fy', c.left.creep_force.y)\n")
    c = ws.contact(y=2e-3, z=-40e-6, V=30, creepage={"xi": 1e-3, "eta": 0.5e-3, "phi": 0}, mu=0.3, method="fastsim")
    assert (c.left.creep_force.x, c.left.creep_force.y) == (ref["Fx"], ref["Fy"])


def test_sweep_rows_are_equilibria(ws):
    s = ws.sweep(y=[0, 2e-3, 4e-3], Q=200e3, threads=2)
    assert isinstance(s.table, pd.DataFrame) and len(s.table) == 3 and s.failed == 0 and len(s.rows) == 3
    assert "Y [N]" in s.table.columns and "left.force.z [N]" in s.table.columns
    for k, y in enumerate([0, 2e-3, 4e-3]):
        e = ws.equilibrium(y=y, Q=200e3)
        assert s.table["y [m]"][k] == y
        assert s.table["Y [N]"][k] == pytest.approx(e.Y, rel=1e-5, abs=1.0)
        assert s.rows[k].left.patches[0].pmax == pytest.approx(e.left.patches[0].pmax, rel=1e-4)


def cone_wheelset():
    # A coned wheel 1:20 on 60E1 without cant, roll fixed: the contact stays where the rail's slope is 1:20, so
    # the rolling radius difference is 2 y / 20 exactly and the equivalent conicity is the cone's slope, 0.05.
    y = np.arange(-30, 40.05, 0.1) * 1e-3
    cone = wrc.profile.points(kind="wheel", name="cone 1:20", y=y, z=y / 20)
    return wrc.wheelset(wheel=cone, rail=wrc.profile.load("profiles/60e1.lua"), cant=0)


def test_geometry_table_of_a_cone():
    t = cone_wheelset().geometry_table(y={"from": -4e-3, "to": 4e-3, "step": 1e-3}, roll="fixed")
    assert isinstance(t, pd.DataFrame) and len(t) == 9
    np.testing.assert_allclose(t["y [m]"], np.linspace(-4e-3, 4e-3, 9), atol=1e-15)
    np.testing.assert_allclose(t["rolling_radius_difference [m]"], 2 * 0.05 * t["y [m]"], atol=1e-8)
    assert "roll_mode" in t.attrs and isinstance(t.attrs["jumps"], list)


def test_conicity_of_a_cone_is_its_slope():
    ws = cone_wheelset()
    for method in ("integral", "harmonic", "regression", "simple"):
        c = ws.conicity(yhat=[1e-3, 3e-3], method=method)
        np.testing.assert_allclose(c.tan_gamma, 0.05, atol=2e-5)
        assert c.method == method and c.roll_mode == "fixed"
    # wrc.conicity on the wheelset's own table gives the same; also from a DataFrame with units in its columns.
    c = ws.conicity(yhat=[2e-3])
    again = wrc.conicity(c.dr, yhat=[2e-3])
    assert again.tan_gamma[0] == c.tan_gamma[0]
    df = pd.DataFrame({"y [m]": c.dr.y, "dr [m]": c.dr.dr})
    assert wrc.conicity(df, yhat=[2e-3]).tan_gamma[0] == c.tan_gamma[0]


def test_conicity_of_a_table():
    y = np.arange(-50, 51) * 0.1e-3
    assert wrc.conicity({"y": y, "dr": 0.2 * y}, yhat=2e-3).tan_gamma[0] == pytest.approx(0.1, abs=1e-12)
    assert wrc.conicity(y=y, dr=0.2 * y, yhat=2e-3).tan_gamma[0] == pytest.approx(0.1, abs=1e-12)  # one table
    dr = 0.2 * y
    dr[9] = np.nan
    with pytest.raises(wrc.Error, match="the 10th point is not a finite number"):
        wrc.conicity({"y": y, "dr": dr}, yhat=2e-3)
    with pytest.raises(wrc.Error, match="leaves the"):
        wrc.conicity({"y": y, "dr": 0.2 * y}, yhat=6e-3)
    with pytest.raises(TypeError, match="mapping"):
        wrc.conicity([1, 2, 3], yhat=2e-3)


def test_trajectory(ws):
    e = ws.equilibrium(y=2e-3, Q=200e3)
    with ws.trajectory() as tr:
        first = tr.contact(y=2e-3, z=e.z, roll=e.roll)
        again = tr.contact(y=2e-3, z=e.z, roll=e.roll)  # warm: the same pose to the solver's tolerance
        cold = ws.contact(y=2e-3, z=e.z, roll=e.roll)
        assert first.force.z == pytest.approx(cold.force.z, rel=1e-6)
        assert again.force.z == pytest.approx(cold.force.z, rel=1e-6)
        w = tr.wheel(side="left", y=2e-3, Fz=100e3)
        assert w.force.z == pytest.approx(100e3, rel=1e-6)
        tr.reset()
        assert tr.contact(y=2e-3, z=e.z, roll=e.roll).force.z == pytest.approx(cold.force.z, rel=1e-6)
    with pytest.raises(wrc.Error, match="closed"):
        tr.contact(y=0, z=-1e-5)
    with pytest.raises(wrc.Error, match="closed"):
        tr.reset()


def test_params_and_four_profiles(s1002, rail60):
    ws = wrc.wheelset(left_wheel=s1002, right_wheel=s1002, left_rail=rail60, right_rail=rail60, gauge=1.437)
    assert ws.params.gauge == 1.437 and ws.params.units["gauge"] == "m"
    one = wrc.wheelset(wheel=s1002, rail=rail60, gauge=1.437)
    assert ws.equilibrium(y=1e-3, Q=100e3).Y == one.equilibrium(y=1e-3, Q=100e3).Y


def test_calls_from_several_threads_equal_serial_calls(ws):
    # Calls release the GIL and take a workspace each: from four Python threads at once they give the serial numbers.
    from concurrent.futures import ThreadPoolExecutor

    ys = [k * 0.5e-3 for k in range(8)]
    serial = [ws.contact(y=y, z=-30e-6).force.z for y in ys]
    with ThreadPoolExecutor(4) as pool:
        parallel = list(pool.map(lambda y: ws.contact(y=y, z=-30e-6).force.z, ys))
    assert parallel == serial


def test_jacobian_with_sensitivity(ws):
    # Each wheel's Jacobian arrives through the same fields as in Lua; its xi column against a difference of the call.
    args = dict(y=0, z=-0.05e-3, roll=0, yaw=0, mu=0.3)
    c = ws.contact(**args, creepage={"xi": 1e-3}, sensitivity=True)
    J = c["left"]["jacobian"]
    for col in ("xi", "eta", "phi", "y", "z", "roll", "yaw"):
        assert np.asarray(J[col]).shape == (6,)
    h = 2e-6
    a = ws.contact(**args, creepage={"xi": 1e-3 + h})["left"]["force"]
    b = ws.contact(**args, creepage={"xi": 1e-3 - h})["left"]["force"]
    assert J["xi"][0] == pytest.approx((a.x - b.x) / (2 * h), rel=0.01)
    w = ws.wheel(side="left", y=0, Fz=100e3, creepage={"xi": 1e-3}, mu=0.3, sensitivity=True)
    assert w["jacobian_fz"]["z"][2] == pytest.approx(1, rel=1e-9)
