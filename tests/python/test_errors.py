"""Bad input from Python: wrong types, NaN, misspelt keys, objects used after close(), missing files. Each is an
exception of the right class carrying the engine's message (the key, the value, what was expected)."""
import math

import numpy as np
import pytest

import wrc


def test_misspelt_keys_name_the_closest(ws, s1002, rail60):
    with pytest.raises(wrc.OptionError, match=r"unknown key 'yaww' \(did you mean 'yaw'\?"):
        ws.equilibrium(y=0, Q=200e3, yaww=0)
    with pytest.raises(wrc.OptionError, match="did you mean 'radius'"):
        wrc.wheelset(wheel=s1002, rail=rail60, raduis=0.45)
    with pytest.raises(wrc.OptionError, match="did you mean 'method'"):
        ws.conicity(yhat=[3e-3], methd="simple")
    with pytest.raises(ValueError):  # an OptionError is a ValueError too
        ws.contact(yy=0)


def test_nan_and_ranges(ws):
    with pytest.raises(wrc.OptionError, match="'y' must be finite"):
        ws.equilibrium(y=math.nan, Q=200e3)
    with pytest.raises(wrc.OptionError, match="'z' must be finite"):
        ws.contact(z=np.float64("nan"))
    with pytest.raises(wrc.OptionError, match="Q = -1"):
        ws.equilibrium(y=0, Q=-1)
    with pytest.raises(wrc.OptionError, match="'Q'"):
        ws.equilibrium(y=0)
    with pytest.raises(wrc.OptionError, match="on_failure"):
        ws.equilibrium(y=0, Q=1e5, on_failure="ignore")
    with pytest.raises(wrc.OptionError, match="finite"):
        ws.sweep(y=[0, float("nan")], Q=1e5)
    # An int beyond a double's range is named with its key (the cast said "Unable to cast Python instance to C++ type").
    with pytest.raises(wrc.OptionError, match=r"'Q': 1000.*beyond the range of a number"):
        ws.equilibrium(y=0, Q=10**400)


def test_wrong_python_types(ws, s1002):
    with pytest.raises(TypeError):
        ws.contact(0.001)  # keywords only, as Lua's table
    with pytest.raises(TypeError, match="'y'"):
        ws.contact(y=object())
    with pytest.raises(TypeError, match="1-D"):
        ws.sweep(y=np.zeros((2, 2)), Q=1e5)
    with pytest.raises(TypeError, match="str"):
        ws.contact(**{"y": 0}, creepage={1: 2})
    # A value of another kind than its key's: the engine's message names the key and what it expected.
    with pytest.raises(wrc.OptionError, match="'y' must be a number"):
        ws.contact(y="3 mm")
    with pytest.raises(wrc.OptionError, match="'wheel' must be a wrc.Profile"):
        wrc.wheelset(wheel="s1002", rail=s1002)
    with pytest.raises(wrc.OptionError, match="'rail'.*required"):
        wrc.wheelset(wheel=s1002)


def ordinal(n):
    """English ordinals, written out here independently of the engine: 1st 2nd 3rd 4th .. 11th 12th 13th .. 21st."""
    if n % 100 in (11, 12, 13):
        return f"{n}th"
    return f"{n}" + {1: "st", 2: "nd", 3: "rd"}.get(n % 10, "th")


def test_positions_are_ordinals_not_lua_indices(ws):
    # Python counts from 0: the NaN planted at y[bad] is the (bad + 1)th value. A message printing "'y'[2]" would send
    # a Python user to the wrong element.
    for bad in (1, 2):
        y = np.array([0, 1e-3, 2e-3, 3e-3])
        y[bad] = np.nan
        with pytest.raises(wrc.OptionError) as e:
            ws.sweep(y=y, Q=200e3)
        assert f"the {ordinal(bad + 1)} value of 'y' must be finite, got NaN" in str(e.value)
        assert "[" not in str(e.value)
    with pytest.raises(wrc.OptionError, match="the 3rd value of 'yhat' must be finite"):
        ws.conicity(yhat=[1e-3, 2e-3, math.inf])


def test_option_types_are_named_as_python_names_them(ws):
    # creepage is a mapping (creepage={"xi": ...}); Lua's "table" and "array" mean nothing to a Python user.
    with pytest.raises(wrc.OptionError) as e:
        ws.contact(y=0, z=-1e-4, creepage=[1e-3], mu=0.3)
    assert "'creepage' must be a dict, got list" in str(e.value)
    with pytest.raises(wrc.OptionError, match="'y' must be a number, got dict"):
        ws.contact(y={"from": 0}, z=-1e-4)
    with pytest.raises(wrc.OptionError, match=r"'y' must be a number, a list or 1-D numpy array of numbers or "
                                              r"dict\(from=, to=, step=\), got str"):
        ws.sweep(y="0..1", Q=200e3)


def test_numpy_scalars_and_none(ws):
    a = ws.contact(y=np.float64(2e-3), z=np.float32(-20e-6))
    b = ws.contact(y=2e-3, z=float(np.float32(-20e-6)), roll=None)  # None: not given (the default)
    assert a.force.z == b.force.z
    assert ws.contact(y=2e-3, z=-20e-6, grids=np.bool_(True)).left.patches[0].pressure.ndim == 2


def test_closed_wheelset(s1002, rail60):
    ws = wrc.wheelset(wheel=s1002, rail=rail60)
    tr = ws.trajectory()
    ws.close()
    for call in (ws.contact, ws.wheel, ws.equilibrium, ws.rigid, ws.sweep, ws.geometry_table, ws.conicity,
                 ws.trajectory):
        with pytest.raises(wrc.Error, match="Wheelset was closed"):
            call(y=0)
    with pytest.raises(wrc.Error, match="closed"):
        ws.params
    # The trajectory made before keeps its wheelset alive.
    assert tr.contact(y=0, z=-20e-6).force.z > 0
    with wrc.wheelset(wheel=s1002, rail=rail60) as w2:
        assert w2.rigid(y=0).converged
    with pytest.raises(wrc.Error, match="closed"):
        w2.rigid(y=0)
    assert "closed" in repr(w2)


def test_engine_errors_keep_their_message(ws):
    with pytest.raises(wrc.Error, match="max_penetration"):
        ws.contact(z=-5e-3)
    with pytest.raises(wrc.Error, match="does not touch"):
        ws.wheel(side="right", y=0.1, Fz=1e5)
