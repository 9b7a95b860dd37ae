"""Ctrl-C (SIGINT) during the calls that run on worker threads: ws.sweep, a batch, ws.geometry_table, ws.conicity and
the strategy check of wrc.wheelset(check_strategy=N) from Python, a sweep of `wrc run`.

Each runs in a child process, is sent SIGINT once its progress line shows a case or element solved (the marker that
it is under way), and must end long before the whole call would have: the reference is the call's own length, the
time its first case took times the cases each thread has left, and the bound a tenth of that. A Python call must
raise KeyboardInterrupt, return nothing and leave no thread of the engine running; `wrc run` ends on the signal and
leaves no output file, whole or part."""
import os
import select
import signal
import subprocess
import sys
import textwrap
import time

import pytest

from conftest import BUILD, SOURCE

CASES = 400  # each solved cold (chain = 1): ~0.2 s apiece on two threads of a Release build, ~40 s in all
THREADS = 2
PROLOGUE = textwrap.dedent(f"""\
    import os, time
    import numpy as np
    import wrc
    ws = wrc.wheelset(wheel=wrc.profile.load("{SOURCE}/profiles/s1002.lua"),
                      rail=wrc.profile.load("{SOURCE}/profiles/60e1.lua"), grid=0.4e-3)
    threads = lambda: len(os.listdir("/proc/self/task"))  # the process's threads, Python's and the engine's
    before = threads()
    got = None
    """)
EPILOGUE = textwrap.dedent("""\
    except KeyboardInterrupt:
        print(f"interrupted: threads {threads()} of {before} before, result {got!r}", flush=True)
        raise
    print("ran to its end", flush=True)
    """)


def interrupt(argv, marker, env=None, delay=0.0):
    """Runs argv, waits for `marker` on its stderr (a progress line) and `delay` s more, sends SIGINT. Returns (seconds
    from the start to the marker, seconds from SIGINT to the end, returncode, stdout, stderr)."""
    t0 = time.perf_counter()
    child = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env, cwd=str(SOURCE))
    err = b""
    try:
        while marker not in err:
            ready, _, _ = select.select([child.stderr], [], [], 300)
            chunk = os.read(child.stderr.fileno(), 4096) if ready else b""
            assert chunk, f"no {marker!r} before the child ended or stalled: {err.decode(errors='replace')}"
            err += chunk
        started = time.perf_counter() - t0
        time.sleep(delay)
        child.send_signal(signal.SIGINT)
        t1 = time.perf_counter()
        out, rest = child.communicate(timeout=600)
        stopped = time.perf_counter() - t1
    finally:
        if child.poll() is None:
            child.kill()
            child.wait()
    return started, stopped, child.returncode, out.decode(), (err + rest).decode(errors="replace")


def python_env():
    return dict(os.environ, PYTHONPATH=str(BUILD / "python"))


def check_stopped(started, stopped, cases_per_thread):
    # `started` includes the interpreter's and the wheelset's start: the first case takes less, the others about as
    # long (cold starts), so the whole call would have taken at least cases_per_thread times the first case.
    first_case = started
    assert stopped < 0.1 * cases_per_thread * first_case or stopped < 2.0, (stopped, started)


def test_ctrl_c_stops_a_python_sweep():
    script = PROLOGUE + textwrap.dedent(f"""\
        try:
            got = ws.sweep(y=np.linspace(-8e-3, 8e-3, {CASES}), Q=200e3, chain=1, threads={THREADS}, progress=True)
        """) + EPILOGUE
    started, stopped, code, out, err = interrupt([sys.executable, "-c", script], b"sweep: 1 / ", python_env())
    assert "ran to its end" not in out, out
    assert code == -signal.SIGINT and "KeyboardInterrupt" in err, (code, err)
    # no result, and the engine's threads (the sweep's runner and workers) have ended
    words = out.split()
    assert "result None" in out and words[2] == words[4], out
    check_stopped(started, stopped, CASES / THREADS)


def test_ctrl_c_stops_a_batch_on_every_core_and_leaves_no_thread():
    elements = 20 * CASES  # cold wheel solves of ~5 ms; without grids, within a batch's memory budget (2.7 GB)
    script = PROLOGUE + textwrap.dedent(f"""\
        try:
            # the marker: a first call that finishes, then the batch on every core
            ws.wheel(side="left", y=0.0, Fz=100e3)
            print("batch", flush=True, file=__import__("sys").stderr)
            got = ws.wheel(side="left", y=np.linspace(0, 7e-3, {elements}), Fz=100e3, threads=0, grids=False)
        """) + EPILOGUE
    started, stopped, code, out, err = interrupt([sys.executable, "-c", script], b"batch", python_env())
    assert code == -signal.SIGINT and "KeyboardInterrupt" in err, (code, err)
    words = out.split()
    assert "result None" in out and words[2] == words[4], out
    assert stopped < 5.0, stopped  # the whole batch: elements / cores x ~5 ms, over 20 s on two cores


def test_ctrl_c_stops_a_geometry_table_and_writes_no_file(tmp_path):
    csv = tmp_path / "table.csv"
    rows = 50000  # at yaw 10 mrad (the 3-D search) ~1.5 ms a row: over a minute on two cores
    script = PROLOGUE + textwrap.dedent(f"""\
        try:
            got = ws.geometry_table(y=np.linspace(-8e-3, 8e-3, {rows}), yaw=0.01, threads={THREADS}, progress=True,
                                    csv="{csv}")
        """) + EPILOGUE
    started, stopped, code, out, err = interrupt([sys.executable, "-c", script], b"geometry table: 1 / ",
                                                 python_env())
    assert code == -signal.SIGINT and "KeyboardInterrupt" in err, (code, err)
    words = out.split()
    assert "result None" in out and words[2] == words[4], out
    assert not csv.exists() and not list(tmp_path.iterdir()), list(tmp_path.iterdir())
    assert stopped < 5.0, stopped


@pytest.mark.parametrize("call", ["wheelset", "conicity"])
def test_ctrl_c_stops_a_wheelset_check_and_a_conicity(call):
    # No progress line marks these: the marker is printed just before the call, the signal 1.5 s after it, once the
    # call's arguments are read (a signal while they are, caught there, is test_errors.py's) and its solves run.
    if call == "wheelset":  # a million poses against brute force: hours
        run = f"""got = wrc.wheelset(wheel=wrc.profile.load("{SOURCE}/profiles/s1002.lua"),
                                rail=wrc.profile.load("{SOURCE}/profiles/60e1.lua"), check_strategy=1000000)"""
    else:  # the conicity's own table: 10 mm either side every 0.4 um at yaw 10 mrad, ~1 ms a row
        run = "got = ws.conicity(yhat=[3e-3], y=np.arange(-10e-3, 10e-3, 4e-7), yaw=0.01)"
    script = PROLOGUE + textwrap.dedent(f"""\
        try:
            print("calling", flush=True, file=__import__("sys").stderr)
            {run}
        """) + EPILOGUE
    started, stopped, code, out, err = interrupt([sys.executable, "-c", script], b"calling", python_env(), delay=1.5)
    assert code == -signal.SIGINT and "KeyboardInterrupt" in err, (code, err)
    words = out.split()
    assert "result None" in out and words[2] == words[4], out
    assert stopped < 5.0, stopped


def test_ctrl_c_ends_a_lua_sweep_and_leaves_no_output(tmp_path):
    out_file = tmp_path / "sweep.csv"
    script = tmp_path / "sweep.lua"
    script.write_text(textwrap.dedent(f"""\
        local ws = wrc.wheelset{{wheel = wrc.profile.load("profiles/s1002.lua"),
                                rail = wrc.profile.load("profiles/60e1.lua"), grid = 0.4e-3}}
        local ys = {{}}
        for i = 0, {CASES - 1} do ys[#ys + 1] = -8e-3 + 16e-3 * i / {CASES - 1} end
        local f = wrc.fs.open_atomic("{out_file}")  -- open before the sweep: written only once it is whole
        f:write("y,Y_Q\\n")
        local s = ws:sweep{{y = ys, Q = 200e3, chain = 1, threads = {THREADS}, progress = true}}
        for _, c in ipairs(s) do f:write(c.y, ",", c.Y_Q, "\\n") end
        f:commit()
        """))
    started, stopped, code, out, err = interrupt([str(BUILD / "wrc"), "run", str(script)], b"sweep: 1 / ")
    assert code == -signal.SIGINT, (code, err)  # SIGINT's default action: the process ends at once
    assert not out_file.exists()
    check_stopped(started, stopped, CASES / THREADS)
