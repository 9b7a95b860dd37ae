"""Batch calls against a Python loop and against Lua: n wheel solves of S1002 on 60E1 (the README's wheelset), y
spread evenly over 0 .. 7 mm, Fz = 100 kN on the left wheel. Prints figures, asserts nothing about speed (the machine
may be loaded); it does check that the three ways give the same lateral forces.

  PYTHONPATH=build/python /usr/bin/python3 tests/bench/bench_python.py --wrc build/wrc [--n 200] [--repeat 3]

Figures, each the best of --repeat runs:
  - batch (threads = all cores, and threads = 1) and the loop of one-by-one ws.wheel calls: wall seconds and ratios;
    a batch's wall split into its solves (b.seconds, the worker threads' run) and what the call does after them
    (the rest: turning the results into a wrc.Batch); then the first read of a field (b.force.y) and of b.items
    (every element's wrc.Result), made when first read;
  - Lua: the same calls in tests/bench/bench_wheel.lua run by the wrc executable (os.clock inside Lua);
  - the Python overhead per call: (loop - batch on one thread) / n, against the engine's time per call (the batch on
    one thread, whose elements are the same calls without Python between them). The loop reads each result's
    force.y, as the Lua loop does: a call's Results are made as they are read, so the figure holds the reading of
    one field; making all of a call's Results (the first read of b.items / n, or r.to_dict()) is printed apart.
"""
import argparse
import gc
import os
import re
import subprocess
import sys
import time

import numpy as np

import wrc

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


def best_of(repeat, f):
    """The best wall and process-CPU seconds of `repeat` runs of f, and f's result of the run of the best wall."""
    wall, cpu, out = float("inf"), float("inf"), None
    for _ in range(repeat):
        w0, c0 = time.perf_counter(), time.process_time()
        got = f()
        w, c = time.perf_counter() - w0, time.process_time() - c0
        if w < wall:
            wall, out = w, got
        cpu = min(cpu, c)
    return wall, cpu, out


def first_read(f):
    """The wall and process-CPU seconds of f()."""
    w0, c0 = time.perf_counter(), time.process_time()
    f()
    return time.perf_counter() - w0, time.process_time() - c0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=200)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--wrc", help="the wrc executable, for the Lua figure (skipped when not given)")
    a = ap.parse_args()

    ws = wrc.wheelset(wheel=wrc.profile.load(os.path.join(ROOT, "profiles/s1002.lua")),
                      rail=wrc.profile.load(os.path.join(ROOT, "profiles/60e1.lua")))
    ys = np.linspace(0, 7e-3, a.n)
    cores = os.cpu_count()

    ws.wheel(side="left", y=0.0, Fz=100e3)  # the first call makes the FFT plans
    t_batch, c_batch, b = best_of(a.repeat, lambda: ws.wheel(side="left", y=ys, Fz=100e3))
    t_batch1, c_batch1, b1 = best_of(a.repeat, lambda: ws.wheel(side="left", y=ys, Fz=100e3, threads=1))
    def loop_calls():
        out = []
        for y in ys:
            w = ws.wheel(side="left", y=float(y), Fz=100e3)
            w.force.y  # what the caller reads (bench_wheel.lua sums it too)
            out.append(w)
        return out

    t_loop, c_loop, loop = best_of(a.repeat, loop_calls)
    gc.collect()  # not a pass over the loop's Results inside the first reads
    (t_field, c_field), (t_items, c_items) = first_read(lambda: b.force.y), first_read(lambda: b.items)
    fy_loop = np.array([w.force.y for w in loop])
    assert not b.errors and not b1.errors, (b.errors, b1.errors)
    assert np.array_equal(b.force.y, fy_loop) and np.array_equal(b1.force.y, fy_loop), "batch differs from the loop"

    load = os.getloadavg()[0]
    print(f"{a.n} wheel solves (S1002/60E1, y = 0 .. 7 mm, Fz = 100 kN), best of {a.repeat}; load average "
          f"{load:.1f} on {cores} cores (wall figures need an idle machine):")
    for t, c, x in ((t_batch, c_batch, b), (t_batch1, c_batch1, b1)):
        print(f"  python batch, threads = {x.threads}:  wall {t:.4f} s, cpu {c:.4f} s   (wall: solves {x.seconds:.4f} s "
              f"+ after them {t - x.seconds:.4f} s)")
    print(f"  first read of b.force.y: wall {t_field * 1e3:.3f} ms, cpu {c_field * 1e3:.3f} ms; of b.items ({b.size} "
          f"wrc.Result): wall {t_items:.4f} s, cpu {c_items:.4f} s")
    print(f"  python loop of calls:       wall {t_loop:.4f} s, cpu {c_loop:.4f} s")
    print(f"  loop / batch ({b.threads} threads), wall = {t_loop / t_batch:.2f}x   (goal on 2 cores: >= 1.7x); "
          f"with b.items read: {t_loop / (t_batch + t_items):.2f}x")
    if a.wrc:
        lua = subprocess.run([a.wrc, "run", os.path.join(ROOT, "tests/bench/bench_wheel.lua"), f"n={a.n}",
                              f"repeat={a.repeat}", f"root={ROOT}"], capture_output=True, text=True, check=True)
        m = re.search(r"in ([0-9.eE+-]+) s .*sum of force.y = ([0-9.eE+-]+) N", lua.stdout)
        t_lua, lua_sum = float(m.group(1)), float(m.group(2))
        # the same solves give the same forces, summed in the same order (%.17g prints a double exactly)
        assert lua_sum == sum(fy_loop.tolist()), f"Lua's forces differ: sum {lua_sum!r} against {sum(fy_loop.tolist())!r}"
        print(f"  lua loop (wrc run):               cpu {t_lua:.4f} s (os.clock)   python loop / lua, cpu = "
              f"{c_loop / t_lua:.3f}")
    per_call = (c_loop - c_batch1) / a.n
    engine = c_batch1 / a.n
    print(f"  python overhead per call (cpu: loop - batch on 1 thread): {per_call * 1e6:.1f} us against "
          f"{engine * 1e3:.3f} ms of engine time per call = {100 * per_call / engine:.2f} %   (goal: < 5 %); making "
          f"all of a call's Results, when read (b.items / n): {c_items / a.n * 1e6:.1f} us")
    return 0


if __name__ == "__main__":
    sys.exit(main())
