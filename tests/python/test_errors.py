"""Bad input from Python: wrong types, NaN, misspelt keys, objects used after close(), missing files. Each is an
exception of the right class carrying the engine's message (the key, the value, what was expected)."""
import collections.abc
import gc
import math
import numbers

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


def test_numpy_scalars_that_item_cannot_make_python(ws):
    # numpy.longdouble.item() gives a longdouble again (no Python type holds it): the conversion recursed until the
    # interpreter crashed. A real one is a number (the same double as float() makes of it), a complex one no option's.
    y = np.longdouble("2e-3")
    assert ws.contact(y=y, z=-20e-6).force.z == ws.contact(y=float(y), z=-20e-6).force.z
    assert ws.conicity(yhat=np.longdouble("3e-3")).tan_gamma[0] == ws.conicity(yhat=3e-3).tan_gamma[0]
    with pytest.raises(TypeError, match="'y'.*got (complex256|clongdouble)"):
        ws.contact(y=np.clongdouble(1e-3), z=-20e-6)


def test_a_misspelt_key_is_named_before_the_key_it_hid(ws):
    # A typo of a required key made the reader say only that the required one was missing ('yhat' is required), the
    # misspelt key given never named. Each message must name the key given and the key meant.
    cases = [
        (lambda: ws.conicity(yaht=[3e-3]), "yaht", "yhat"),
        (lambda: ws.equilibrium(y=0, q=200e3), "q", "Q"),  # another case: 'Q', not 'y' (also one edit away)
        (lambda: ws.wheel(side="left", y=0, FZ=1e5), "FZ", "Fz"),
        (lambda: ws.geometry_table(yy=[0, 1e-3]), "yy", "y"),
        (lambda: ws.sweep(y=[0], q=1e5), "q", "Q"),
        (lambda: ws.equilibrium(y=[0, 1e-3], q=200e3), "q", "Q"),  # a batch: every element alike, raised
        (lambda: ws.geometry_table(y={"from": 0, "too": 1e-3, "step": 1e-3}), "too", "to"),
        (lambda: wrc.conicity(y=[0, 1e-3, 2e-3], drr=[0, 1e-4, 2e-4], yhat=1e-3), "drr", "dr"),
        (lambda: wrc.conicity({"y": [0, 1e-3, 2e-3], "drr": [0, 1e-4, 2e-4]}, yhat=1e-3), "drr", "dr"),
        (lambda: wrc.conicity({"y": [0, 1e-3, 2e-3], "dr": [0, 1e-4, 2e-4]}, yhaat=1e-3), "yhaat", "yhat"),
    ]
    for call, given, meant in cases:
        with pytest.raises(wrc.OptionError) as e:
            call()
        assert f"unknown key '{given}' (did you mean '{meant}'?" in str(e.value), str(e.value)
    # Without a typo the error is the one it was.
    with pytest.raises(wrc.OptionError, match="'yhat' is required"):
        ws.conicity(method="simple")
    with pytest.raises(wrc.OptionError, match="'y' must be finite"):
        ws.contact(y=math.nan, z=0)


def test_conicity_arguments_are_checked_as_they_are_read(ws):
    # Checked only when the computation began, these were wrc.Error (not the OptionError of a bad argument) and named
    # wrc.conicity whichever call was made (the C API then said "wrc_conicity: wrc.conicity: ...").
    for call, words in (
        (lambda: ws.conicity(yhat=[]), "Wheelset.conicity: 'yhat' needs at least one amplitude"),
        (lambda: ws.conicity(yhat=[-1e-3]), "Wheelset.conicity: the amplitude yhat = -0.001 m must be a positive"),
        (lambda: wrc.conicity(y=[0, 1e-3, 2e-3], dr=[0, 1e-4], yhat=1e-3), "wrc.conicity: y has 3 values but dr has 2"),
        (lambda: wrc.conicity({"y": [0, 1e-3, 2e-3], "dr": [0, math.nan, 2e-4]}, yhat=1e-3),
         "wrc.conicity: Δr table: the 2nd point is not a finite number"),
        (lambda: wrc.conicity(y=[0, 2e-3, 1e-3], dr=[0, 1e-4, 2e-4], yhat=1e-3),
         "wrc.conicity: y must increase strictly: the 3rd value of y"),
    ):
        with pytest.raises(wrc.OptionError) as e:
            call()
        assert str(e.value).startswith(words), str(e.value)
    # A cone's table, Δr = 2 (1/20) y: tan γe = 1/20 for an amplitude inside it.
    y = np.linspace(-5e-3, 5e-3, 11)
    assert wrc.conicity(y=y, dr=2 * y / 20, yhat=2e-3, method="simple").tan_gamma[0] == pytest.approx(0.05, rel=1e-12)


def test_a_path_holding_nul_is_refused(tmp_path, s1002):
    # The system reads a path up to its first NUL: "w.txt\0.csv" was written as w.txt and "x.txt\0junk" read x.txt,
    # files the caller did not name. The folder itself shows that nothing was written at the cut name.
    cut = tmp_path / "cut.txt"
    with pytest.raises(wrc.Error, match="holds a NUL character"):
        s1002.write(str(cut) + "\0.csv")
    assert not cut.exists()
    cut.write_text("-30 -9\n0 0\n30 -9\n")
    with pytest.raises(wrc.ProfileError, match=r"cut.txt\\0junk' holds a NUL character"):
        wrc.profile.load(str(cut) + "\0junk", kind="rail")
    assert len(wrc.profile.load(cut, kind="rail")) == 3


def test_an_error_inside_an_isinstance_check_propagates(ws):
    # Whether a value is a number or a mapping is asked of the numbers and collections.abc ABCs, whose checks run
    # Python code: a pending Ctrl-C raises KeyboardInterrupt there. Here ABCs below numbers.Real and Mapping raise in
    # their subclass hooks, which isinstance(x, Real or Mapping) consults for a type it has not seen (the same path);
    # the error must reach the caller, not turn into "expected a number ..., got Probe" (the interrupt lost).
    import pandas  # noqa: F401 -- imported before the hostile classes exist (its import checks types of its own)

    def hostile(base):
        class Hostile(base):
            @classmethod
            def __subclasshook__(cls, other):
                raise RuntimeError("raised inside the isinstance check")
        return Hostile

    class Probe:
        pass

    hostiles = [hostile(numbers.Real), hostile(collections.abc.Mapping)]
    try:
        with pytest.raises(RuntimeError, match="raised inside the isinstance check"):
            ws.rigid(y=Probe())  # the options' conversion
        with pytest.raises(RuntimeError, match="raised inside the isinstance check"):
            wrc.conicity(Probe(), yhat=[3e-3])  # the table's check
    finally:
        del hostiles
        gc.collect()  # the ABCs forget their subclasses (weak references): later checks are plain again
    with pytest.raises(TypeError, match="expected a number"):
        ws.rigid(y=Probe())
    with pytest.raises(TypeError, match="the table must be a mapping"):
        wrc.conicity(Probe(), yhat=[3e-3])
