"""Batch calls (python/wrc/batch.py, engine/src/python/batch_binding.cpp): arrays for the number arguments of
Wheelset.contact, .wheel, .equilibrium and .rigid.

The reference of every batch is the same calls made one by one (each a fresh, cold call of the engine): a batch must
equal them bit for bit (np.array_equal on every field, NaN where a field is NaN in both), on one or two threads."""
import ctypes
import gc
import os
import re
import resource
import signal
import threading
import time

import numpy as np
import pytest

import wrc

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


@pytest.fixture(scope="module")
def ws():
    return wrc.wheelset(wheel=wrc.profile.load(os.path.join(ROOT, "profiles/s1002.lua")),
                        rail=wrc.profile.load(os.path.join(ROOT, "profiles/60e1.lua")), grid=0.4e-3)


def same(a, b, where="result"):
    """a and b the same values: results field by field, lists item by item, arrays and numbers bit for bit."""
    if isinstance(a, wrc.Result):
        assert isinstance(b, wrc.Result), where
        assert list(a.keys()) == list(b.keys()), where
        for k in a.keys():
            same(a[k], b[k], f"{where}.{k}")
    elif isinstance(a, list):
        assert isinstance(b, list) and len(a) == len(b), where
        for i, (x, y) in enumerate(zip(a, b)):
            same(x, y, f"{where}[{i}]")
    elif isinstance(a, np.ndarray):
        assert a.dtype == b.dtype and a.shape == b.shape, where
        assert np.array_equal(a, b, equal_nan=a.dtype.kind == "f"), where
    elif isinstance(a, float):
        assert isinstance(b, float) and (a == b or (np.isnan(a) and np.isnan(b))), f"{where}: {a!r} != {b!r}"
    else:
        assert type(a) is type(b) and a == b, f"{where}: {a!r} != {b!r}"


def one_by_one(method, shape, **kwargs):
    """The calls of a batch made alone: kwargs broadcast here with numpy's own rules, element by element."""
    arrays = {k: np.asarray(v) for k, v in kwargs.items() if isinstance(v, (list, np.ndarray))}
    nested = {(k, j): np.asarray(x) for k, v in kwargs.items() if isinstance(v, dict)
              for j, x in v.items() if isinstance(x, (list, np.ndarray))}
    out = np.empty(shape, dtype=object)
    for index in np.ndindex(*shape):
        call = dict(kwargs)
        for k, a in arrays.items():
            call[k] = float(np.broadcast_to(a, shape)[index])
        for (k, j), a in nested.items():
            call[k] = dict(call[k], **{j: float(np.broadcast_to(a, shape)[index])})
        out[index] = method(**call)
    return out


def check_batch(method, shape, **kwargs):
    """The batch on 1 and 2 threads against the calls one by one: every item and every stacked field."""
    alone = one_by_one(method, shape, **kwargs)
    batches = [method(threads=t, **kwargs) for t in (1, 2)]
    for b in batches:
        assert isinstance(b, wrc.Batch)
        assert b.shape == shape and b.errors == [] and b.ok.all()
        for index in np.ndindex(*shape):
            same(b.items[index], alone[index], f"items{index}")
    b = batches[1]
    assert b.threads == min(2, int(np.prod(shape)))
    # stacked fields: each element's value at its index
    for key in ("converged", "iterations", "z", "Fz", "Y_Q", "y", "yaw"):
        if key in b.keys():
            got = getattr(b, key)
            assert got.shape == shape
            want = np.array([alone[i][key] for i in np.ndindex(*shape)]).reshape(shape)
            assert got.dtype == want.dtype and np.array_equal(got, want), key
    return batches[1], alone


def test_wheel_batch_equals_the_calls_one_by_one(ws):
    b, alone = check_batch(ws.wheel, (5,), side="left", y=np.linspace(0, 7e-3, 5), Fz=100e3)
    assert np.array_equal(b.force.y, [w.force.y for w in alone])
    assert np.array_equal(b.force.z, [w.force.z for w in alone])
    # patches: padded with NaN to the longest, with their count
    counts = [len(w.patches) for w in alone]
    assert np.array_equal(b.patches.count, counts)
    assert len(b.patches) == max(counts)
    pmax = b.patches.pmax
    assert pmax.shape == (5, max(counts))
    for i, w in enumerate(alone):
        for k in range(max(counts)):
            want = w.patches[k].pmax if k < counts[i] else np.nan
            assert np.array_equal(pmax[i, k], want, equal_nan=True)
            assert np.array_equal(b.patches[k].pmax[i], want, equal_nan=True)


def test_wheel_with_rolling_keys(ws):
    b, alone = check_batch(ws.wheel, (3,), side="left", y=[0.0, 2e-3, 4e-3], yaw=np.array([-1e-3, 0, 1e-3]),
                           Fz=80e3, V=30.0, mu=0.3)
    assert np.array_equal(b.creep_force.y, [w.creep_force.y for w in alone])


def test_contact_frictionless_and_with_a_creepage_column(ws):
    b, alone = check_batch(ws.contact, (3,), y=np.array([0, 1e-3, 2e-3]), z=-40e-6)
    assert np.array_equal(b.left.force.z, [c.left.force.z for c in alone])
    # a nested key batched beside a shared one, broadcast against y: shape (2, 3)
    b, alone = check_batch(ws.contact, (2, 3), y=np.array([[0.0], [3e-3]]), z=-40e-6, V=30.0, mu=0.3,
                           creepage={"xi": np.array([-1e-3, 0, 1e-3]), "eta": 5e-4})
    assert np.array_equal(b.creep_force.x, np.array([[c.creep_force.x for c in row] for row in alone]))


def test_equilibrium_and_rigid(ws):
    b, alone = check_batch(ws.equilibrium, (3,), y=np.array([0, 2e-3, 4e-3]), Q=200e3)
    assert np.array_equal(b.Y_Q, [e.Y_Q for e in alone])
    b, alone = check_batch(ws.rigid, (2, 2), y=np.array([[-2e-3], [3e-3]]), yaw=[0.0, 2e-3])
    assert b.shape == (2, 2)


def test_broadcasting_shapes(ws):
    b = ws.rigid(y=np.zeros((3, 1)), yaw=np.zeros((1, 4)))
    assert b.shape == (3, 4) and b.size == 12 and b.items.shape == (3, 4)
    assert b.y.shape == (3, 4)
    b = ws.rigid(y=np.linspace(0, 1e-3, 4).reshape(2, 2), yaw=0.0)
    assert b.shape == (2, 2)
    assert np.array_equal(b.y, np.linspace(0, 1e-3, 4).reshape(2, 2))
    assert ws.rigid(y=[]).shape == (0,)
    with pytest.raises(wrc.OptionError, match="do not broadcast together: y \\(2,\\), yaw \\(3,\\)"):
        ws.rigid(y=[0.0, 1e-3], yaw=[0.0, 1e-3, 2e-3])
    with pytest.raises(ValueError):  # OptionError is a ValueError
        ws.rigid(y=[0.0, 1e-3], yaw=[0.0, 1e-3, 2e-3])


def test_a_failing_element_is_recorded_and_the_others_are_solved(ws):
    ys = np.array([0.0, np.nan, 3e-3])
    b = ws.wheel(side="left", y=ys, Fz=100e3, threads=2)
    assert np.array_equal(b.ok, [True, False, True])
    assert len(b.errors) == 1
    e = b.errors[0]
    assert isinstance(e, wrc.OptionError) and e.index == (1,)
    with pytest.raises(wrc.OptionError) as alone:
        ws.wheel(side="left", y=float("nan"), Fz=100e3)
    assert str(e) == str(alone.value) and "'y'" in str(e)
    assert b.items[1] is None and np.isnan(b.force.y[1]) and np.isnan(b.converged[1])
    for i in (0, 2):
        same(b.items[i], ws.wheel(side="left", y=float(ys[i]), Fz=100e3))
        assert b.force.y[i] == b.items[i].force.y
    # an error of the solve (pressed 5 mm in) is a wrc.Error, not an OptionError, with the one-by-one message
    c = ws.contact(y=0.0, z=[-40e-6, -5e-3])
    assert np.array_equal(c.ok, [True, False])
    with pytest.raises(wrc.Error) as alone:
        ws.contact(y=0.0, z=-5e-3)
    assert type(c.errors[0]) is wrc.Error and str(c.errors[0]) == str(alone.value)


def test_not_converged_elements(ws):
    # a load the wheel carries only deeper than max_penetration: out of reach
    kw = dict(side="left", y=0.0, max_penetration=40e-6)
    b = ws.wheel(Fz=[20e3, 400e3], **kw)
    assert np.array_equal(b.ok, [True, False])
    e = b.errors[0]
    assert isinstance(e, wrc.NotConverged) and e.index == (1,)
    assert e.result.converged is False
    with pytest.raises(wrc.NotConverged) as alone:
        ws.wheel(Fz=400e3, **kw)
    assert str(e) == str(alone.value)
    same(e.result, alone.value.result)
    assert np.isnan(b.z[1])  # not in the arrays: a failure
    # on_failure = "return": the element is a result with converged = False, in the arrays
    r = ws.wheel(Fz=[20e3, 400e3], on_failure="return", **kw)
    assert r.errors == [] and r.ok.all()
    assert np.array_equal(r.converged, [True, False])
    same(r.items[1], alone.value.result)


def test_threads_one_and_two_give_the_same_batch(ws):
    kw = dict(side="right", y=np.linspace(-3e-3, 5e-3, 6), Fz=np.array([60e3, 120e3]).reshape(2, 1))
    one, two = ws.wheel(threads=1, **kw), ws.wheel(threads=2, **kw)
    assert one.threads == 1 and two.threads == 2
    for index in np.ndindex(*one.shape):
        same(one.items[index], two.items[index])
    for key in ("z", "approach", "residual", "iterations"):
        assert np.array_equal(getattr(one, key), getattr(two, key))


def test_bad_input(ws):
    with pytest.raises(TypeError, match="'y' must be a number or an array of numbers, got an array of <U"):
        ws.rigid(y=["a", "b"])
    with pytest.raises(TypeError, match="'y' must be a number or an array of numbers"):
        ws.rigid(y=[[0.0, 1.0], [0.0]])
    with pytest.raises(TypeError, match="complex"):
        ws.rigid(y=np.array([1j]))
    # a misspelt key fails every element alike: raised, naming the closest key as a one-by-one call does
    # once, with how many elements fail so and the first one's index (.index, as the recorded errors have)
    with pytest.raises(wrc.OptionError) as batch:
        ws.rigid(y=[0.0, 1e-3], yaww=0.0)
    with pytest.raises(wrc.OptionError) as alone:
        ws.rigid(y=0.0, yaww=0.0)
    assert "yaw" in str(alone.value)
    assert str(batch.value) == f"{alone.value} (every element of the batch fails so: all 2, the first at index (0,))"
    assert batch.value.index == (0,)
    with pytest.raises(wrc.OptionError, match=re.escape("'Fz' must be finite, got NaN (every element of the batch "
                                                        "fails so: all 6, the first at index (0, 0))")) as e:
        ws.wheel(side="left", y=np.zeros((2, 3)), Fz=np.nan)
    assert e.value.index == (0, 0)
    # the same bad value in some elements only is theirs: recorded, the others solved
    b = ws.wheel(side="left", y=np.zeros(3), Fz=[np.nan, 100e3, np.nan])
    assert np.array_equal(b.ok, [False, True, False]) and [x.index for x in b.errors] == [(0,), (2,)]
    # threads= is read as every call reads it (a sweep's, a geometry table's): a whole number in 0..256, of any
    # Python or numpy kind; anything else is named with its value.
    for bad, said in ((-1, "got -1"), (257, "got 257"), (10**30, "got 1e+30"), (1.5, "got 1.5"), ("2", "got str"),
                      (True, "got bool")):
        with pytest.raises(wrc.OptionError, match="Wheelset.rigid: 'threads' must be .*" + re.escape(said)):
            ws.rigid(y=[0.0], threads=bad)
        with pytest.raises(wrc.OptionError, match="Wheelset.sweep: 'threads' must be .*" + re.escape(said)):
            ws.sweep(y=[0.0], Q=1e5, threads=bad)
    for good in (np.int64(1), np.uint8(1), 1.0, 1):
        assert ws.rigid(y=[0.0, 1e-3], threads=good).threads == 1
    assert ws.rigid(y=[0.0, 1e-3], threads=256).threads == 2  # never more than the elements
    with pytest.raises(wrc.OptionError, match="threads = is an option of batch calls"):
        ws.rigid(y=0.0, threads=2)
    assert "creepage.xi" in wrc.batch_keys("wheel") and "Fz" in wrc.batch_keys("wheel")
    assert "side" not in wrc.batch_keys("wheel")
    with pytest.raises(wrc.Error, match="not an operation of batch calls"):
        wrc.batch_keys("sweep")


def test_keyboard_interrupt_stops_between_elements(ws):
    ys = np.linspace(0, 7e-3, 10000)  # tens of seconds of solves (3.4 GB of results without grids, within the budget)
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    t0 = time.perf_counter()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        ws.wheel(side="left", y=ys, Fz=100e3, threads=2, grids=False)
    elapsed = time.perf_counter() - t0
    timer.join()
    assert elapsed < 3.0, elapsed  # stopped, not run to the end
    # the wheelset still works
    assert ws.wheel(side="left", y=0.0, Fz=100e3).converged


def results_alive():
    return sum(isinstance(o, wrc.Result) for o in gc.get_objects())


def test_items_are_made_when_first_read_and_fields_do_not_depend_on_it(ws):
    kw = dict(side="left", y=np.linspace(0, 7e-3, 4), Fz=np.array([100e3, 100e3, np.nan, 100e3]), threads=2)
    gc.collect()
    before = results_alive()
    fields_first = ws.wheel(**kw)
    # no Result per element before b.items is read: the fields come from the engine's results
    fy, pmax, count = fields_first.force.y, fields_first.patches.pmax, fields_first.patches.count
    assert results_alive() == before
    items = fields_first.items
    assert results_alive() > before and fields_first.items is items
    assert items[2] is None and np.isnan(fy[2]) and count[2] == 0
    # read in the other order, and after the wheelset is closed (the batch keeps its results): the same arrays
    items_first = ws.wheel(**kw)
    later = items_first.items
    ws2 = wrc.wheelset(wheel=wrc.profile.load(os.path.join(ROOT, "profiles/s1002.lua")),
                       rail=wrc.profile.load(os.path.join(ROOT, "profiles/60e1.lua")), grid=0.4e-3)
    closed = ws2.wheel(**kw)
    ws2.close()
    del ws2
    for b in (items_first, closed):
        for got, want in ((b.force.y, fy), (b.patches.pmax, pmax), (b.patches.count, count)):
            assert got.dtype == want.dtype and np.array_equal(got, want, equal_nan=True)
    for i in (0, 1, 3):
        same(later[i], items[i], f"items[{i}]")
        same(closed.items[i], items[i], f"items[{i}]")
        same(items[i], ws.wheel(side="left", y=float(kw["y"][i]), Fz=100e3), f"items[{i}]")
        assert fy[i] == items[i].force.y
        assert np.array_equal(pmax[i, :count[i]], [p.pmax for p in items[i].patches])


def count_results(r):
    """The Results of a result made whole: itself and every table and list item under it (reading them all)."""
    n = 1
    for v in r.values():
        for x in (v if isinstance(v, list) else [v]):
            if isinstance(x, wrc.Result):
                n += count_results(x)
    return n


def test_a_calls_results_are_made_as_they_are_read(ws):
    # One call (not a batch): its tables become Results when first read, from the engine's recorded result; what is
    # read equals what the batch's eagerly made items hold (test above: same(items[i], ws.wheel(...))).
    gc.collect()
    before = results_alive()
    w = ws.wheel(side="left", y=3e-3, Fz=100e3)
    assert results_alive() - before == 1  # the result itself, its fields not yet made
    fy = w.force.y
    partly = results_alive() - before
    whole = count_results(w)
    assert whole > 50 and partly < whole / 4, (partly, whole)
    # made whole, it is the batch's item of the same call; its units and repr read the same way
    b = ws.wheel(side="left", y=np.array([3e-3]), Fz=100e3)
    same(w, b.items[0])
    assert fy == b.force.y[0] and w.force.units["y"] == "N"
    assert repr(w).startswith("Result(")


def test_a_calls_result_outlives_its_wheelset():
    ws2 = wrc.wheelset(wheel=wrc.profile.load(os.path.join(ROOT, "profiles/s1002.lua")),
                       rail=wrc.profile.load(os.path.join(ROOT, "profiles/60e1.lua")), grid=0.5e-3)
    w = ws2.wheel(side="left", y=0.0, Fz=100e3)
    ws2.close()
    del ws2
    gc.collect()
    assert w.patches[0].pressure.shape == (w.patches[0].grid.ny, w.patches[0].grid.nx)
    assert w.patches[0].grid.x.shape == (w.patches[0].grid.nx,)
    assert abs(w.force.z) > 0


def test_a_result_pickles_and_copies_as_the_fields_it_holds(ws):
    # A process pool returns results by pickle; the engine's record behind a deferred Result is no Python data, and
    # copy.deepcopy said "a wrc.Result is read-only". The copy must hold every field of the original, bit for bit,
    # whatever of the original was read before.
    import copy
    import pickle

    w = ws.wheel(side="left", y=3e-3, Fz=100e3, grids=True)
    back = pickle.loads(pickle.dumps(w))
    same(back, ws.wheel(side="left", y=3e-3, Fz=100e3, grids=True))  # a fresh call: nothing of it read yet
    same(back, w)
    assert back.units == w.units and back.patches[0].units == w.patches[0].units
    same(copy.deepcopy(w), w)
    b = ws.rigid(y=[0.0, 2e-3])
    same(pickle.loads(pickle.dumps(b.items[1])), ws.rigid(y=2e-3))


def test_a_batch_pickles_and_copies_bit_for_bit(ws):
    # A process pool returns batches by pickle; the engine's results behind a batch were no Python data ("cannot
    # pickle '_BatchNodes' object"). The copy must equal the same calls made afresh, element by element: its items
    # the one-by-one calls, its fields and errors a fresh batch's, whatever of the original was read before.
    import copy
    import pickle

    # shape (2, 3, 3): a NaN load fails (OptionError), 400 kN is out of reach within 40 um (NotConverged)
    kw = dict(side="left", y=np.linspace(0, 7e-3, 3).reshape(3, 1), Fz=np.array([100e3, np.nan, 400e3]),
              max_penetration=np.array([1e-3, 40e-6]).reshape(2, 1, 1), grids=True)
    b = ws.wheel(**kw)
    b.force.y, b.patches[0].pmax  # some fields made before the copy: the copy makes its own
    fresh = ws.wheel(**kw)
    assert {type(x) for x in fresh.errors} == {wrc.OptionError, wrc.NotConverged}  # both kinds of failure
    copies = [pickle.loads(pickle.dumps(b)), pickle.loads(pickle.dumps(b, protocol=0)), copy.deepcopy(b),
              copy.copy(b)]
    for got in copies:
        assert isinstance(got, wrc.Batch) and got.shape == b.shape == (2, 3, 3) and got.size == 18
        assert (got.operation, got.threads, got.seconds) == (b.operation, b.threads, b.seconds)
        assert np.array_equal(got.ok, fresh.ok)
        for name in ("force", "z", "converged", "patches"):  # a table, a number, a bool and a list field
            same_fields(getattr(got, name), getattr(fresh, name), name)
        assert np.array_equal(got.patches.pmax, fresh.patches.pmax, equal_nan=True)
        assert [(type(x), str(x), x.index) for x in got.errors] == [(type(x), str(x), x.index) for x in fresh.errors]
        for x, y in zip(got.errors, fresh.errors):
            if isinstance(x, wrc.NotConverged):
                same(x.result, y.result, f"errors{x.index}.result")
        for index in np.ndindex(*b.shape):
            if not fresh.ok[index]:
                assert got.items[index] is None
                continue
            alone = ws.wheel(side="left", y=float(kw["y"][index[1], 0]), Fz=float(kw["Fz"][index[2]]),
                             max_penetration=float(kw["max_penetration"][index[0], 0, 0]), grids=True)
            same(got.items[index], alone, f"items{index}")
    # a field of a batch pickles too (its part of the results)
    assert np.array_equal(pickle.loads(pickle.dumps(b.force)).y, fresh.force.y, equal_nan=True)
    assert np.array_equal(pickle.loads(pickle.dumps(b.patches)).count, fresh.patches.count)
    # damaged pickled data is refused with a clear error, never read past its end
    remake, (state,) = b._nodes.__reduce__()
    cut = [x[:len(x) // 2] if x is not None else None for x in state[1]]
    with pytest.raises(wrc.Error, match="pickled results are damaged .cut short."):
        remake((state[0], cut))


def same_fields(a, b, where):
    """Two stacked fields of batches the same: arrays bit for bit (NaN where NaN), nodes field by field."""
    if isinstance(a, np.ndarray):
        assert a.dtype == b.dtype and np.array_equal(a, b, equal_nan=a.dtype.kind == "f"), where
        return
    assert type(a) is type(b) and a.keys() == b.keys(), where
    if isinstance(a, wrc.batch.BatchList):
        assert np.array_equal(a.count, b.count), where
        for k in range(len(a)):
            same_fields(a[k], b[k], f"{where}[{k}]")
        return
    for k in a.keys():
        same_fields(getattr(a, k), getattr(b, k), f"{where}.{k}")


def test_a_batch_is_indexed_by_field_names(ws):
    # b[0] and iteration went through __getattr__ with an int: "'int' object has no attribute 'startswith'".
    b = ws.rigid(y=[0.0, 1e-3])
    with pytest.raises(TypeError, match=r"b.items\[index\]"):
        b[0]
    with pytest.raises(TypeError, match=r"b.items\[index\]"):
        b.left[0]
    with pytest.raises(TypeError, match="not iterable"):
        list(b)
    assert "Y_Q" in b and "nope" not in b and 0 not in b
    assert np.array_equal(b["Y_Q"], b.Y_Q) and np.array_equal(b["left"]["normal_force"], b.left.normal_force)


def resident_bytes():
    """The memory the process holds, independent of the engine: its resident pages as the system counts them
    (/proc/self/statm), or under AddressSanitizer (the sanitizer builds) the heap its allocator has handed out, since
    there freed memory sits in a quarantine and leaves the resident pages on the allocator's schedule, not the caller's."""
    try:
        asan = ctypes.CDLL(None).__sanitizer_get_current_allocated_bytes
    except AttributeError:
        with open("/proc/self/statm") as f:
            return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")
    asan.restype = ctypes.c_size_t
    return asan()


def test_a_batch_whose_results_do_not_fit_is_refused_before_it_takes_the_memory(ws):
    # Every element's result is kept until the Batch is dropped: a million rigid elements asked for ~29 GB and the
    # system ended the process (or the broadcast columns alone took GBs). The batch is refused, naming the size and how
    # to split it, before the memory is taken: first on what every element holds whatever its result ...
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss  # KiB
    t0 = time.perf_counter()
    with pytest.raises(wrc.Error, match=r"100000000 elements .* before any result\), more than a batch call keeps "
                                        r"\(4 GB\): split it into batches of at most \d+ elements$"):
        ws.rigid(y=np.broadcast_to(0.0, (10**8,)))  # a view: no memory of its own
    with pytest.raises(wrc.Error, match="10000000000 elements"):
        ws.rigid(y=np.zeros((10**5, 1)), yaw=np.zeros((1, 10**5)))  # a broadcast of 1e10 elements
    # ... then on the results of the first elements solved, projected to the whole batch.
    with pytest.raises(wrc.Error) as e:
        ws.rigid(y=np.linspace(0, 1e-3, 400_000))
    said = re.search(r"about ([\d.]+) GB \(400000 elements of about ([\d.]+) KB each, as the first (\d+) took\), "
                     r"more than a batch call keeps \(4 GB\): split it into batches of at most (\d+) elements$",
                     str(e.value))
    assert said, str(e.value)
    per_element = float(said.group(2)) * 1e3
    assert int(said.group(3)) < 100 and int(said.group(4)) * per_element <= 4e9
    assert time.perf_counter() - t0 < 5 and resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - peak < 500_000
    # The estimate against the memory the system gives a batch that fits (its resident growth while it is held).
    before = resident_bytes()
    kept = ws.rigid(y=np.linspace(0, 1e-3, 4000))
    grown = (resident_bytes() - before) / kept.size
    assert 0.5 < per_element / grown < 2, (per_element, grown)
    with pytest.raises(wrc.Error, match=r"\(or grids = False: no grids kept\)$"):
        ws.wheel(side="left", y=np.zeros(10**5), Fz=100e3)
    with pytest.raises(wrc.Error, match=r"elements$"):
        ws.wheel(side="left", y=np.zeros(10**5), Fz=100e3, grids=False)


def test_a_masked_array_is_refused(ws):
    # np.asarray drops the mask: the masked values were solved as if given.
    with pytest.raises(TypeError, match="'y' is a masked array with 1 masked value"):
        ws.rigid(y=np.ma.array([0, 1e-3], mask=[False, True]))
    assert ws.rigid(y=np.ma.array([0, 1e-3])).size == 2  # nothing masked: its values
