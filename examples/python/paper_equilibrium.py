#!/usr/bin/env python3
"""The paper's wheelset from Python (standard library only: ctypes over libwrc, the C API of wrc/wrc.h).

S1002 wheels on 60E1 rails (1:40, gauge 1435 mm, r0 = 450 mm): the static equilibrium at y = 3 mm under
Q = 200 kN. Prints Y/Q, z, roll and each contact patch (normal force, contact angle, area, peak pressure).

    python3 paper_equilibrium.py [path/to/libwrc.so]

Without an argument the library is looked up as WRC_LIBRARY, then by the system's loader ("libwrc.so.0"). The Python
package (paper_equilibrium_package.py, docs/python.md) does the same with numpy results and Python exceptions."""
import ctypes
import math
import os
import sys


class Wrc:
    """A thin ctypes view of wrc.h: each call checks its status and raises with wrc_last_error()."""

    OK, NOT_CONVERGED = 0, 3

    def __init__(self, path):
        try:
            self.lib = ctypes.CDLL(path)
        except OSError as e:
            sys.exit(f"paper_equilibrium.py: cannot load the C library of wrc '{path}' ({e}).\n"
                     "Install wrc (cmake --install build --prefix /opt/wrc) and give the library as the argument or as "
                     "WRC_LIBRARY=/opt/wrc/lib/libwrc.so.0, or use the Python package: "
                     "examples/python/paper_equilibrium_package.py")
        P = ctypes.c_void_p
        D = ctypes.c_double
        sig = {
            "wrc_version": ([], ctypes.c_char_p), "wrc_last_error": ([], ctypes.c_char_p),
            "wrc_abi_version": ([], ctypes.c_int),
            "wrc_profile_load": ([ctypes.c_char_p, ctypes.c_char_p, ctypes.POINTER(P)], ctypes.c_int),
            "wrc_wheelset_new": ([P, P, ctypes.c_char_p, ctypes.POINTER(P)], ctypes.c_int),
            "wrc_equilibrium": ([P, D, D, D, ctypes.c_char_p, ctypes.POINTER(P)], ctypes.c_int),
            "wrc_result_number": ([P, ctypes.c_char_p, ctypes.POINTER(D)], ctypes.c_int),
            "wrc_result_count": ([P, ctypes.c_char_p, ctypes.POINTER(ctypes.c_size_t)], ctypes.c_int),
            "wrc_profile_free": ([P], ctypes.c_int), "wrc_wheelset_free": ([P], ctypes.c_int),
            "wrc_result_free": ([P], ctypes.c_int),
        }
        for name, (args, res) in sig.items():
            f = getattr(self.lib, name)
            f.argtypes, f.restype = args, res

    def call(self, name, *args, allow=(OK,)):
        status = getattr(self.lib, name)(*args)
        if status not in allow:
            raise RuntimeError(self.lib.wrc_last_error().decode())
        return status

    def new(self, name, *args):
        handle = ctypes.c_void_p()
        self.call(name, *args, ctypes.byref(handle))
        return handle

    def number(self, result, path):
        v = ctypes.c_double()
        self.call("wrc_result_number", result, path.encode(), ctypes.byref(v))
        return v.value

    def count(self, result, path):
        n = ctypes.c_size_t()
        self.call("wrc_result_count", result, path.encode(), ctypes.byref(n))
        return n.value


def main():
    lib = sys.argv[1] if len(sys.argv) > 1 else os.environ.get("WRC_LIBRARY", "libwrc.so.0")
    w = Wrc(lib)
    wheel = w.new("wrc_profile_load", b"profiles/s1002.lua", None)
    rail = w.new("wrc_profile_load", b"profiles/60e1.lua", None)
    ws = w.new("wrc_wheelset_new", wheel, rail, b"gauge=1.435 cant=0.025 radius=0.45")
    e = ctypes.c_void_p()
    w.call("wrc_equilibrium", ws, 3e-3, 0.0, 200e3, b"grids=false", ctypes.byref(e))
    print(f"wrc {w.lib.wrc_version().decode()}, equilibrium at y = 3 mm, Q = 200 kN")
    print(f"Y/Q = {w.number(e, 'Y_Q'):.6f}")
    print(f"z = {w.number(e, 'z') * 1e3:.6f} mm")
    print(f"roll = {w.number(e, 'roll') * 1e3:.6f} mrad")
    for side in ("left", "right"):
        for i in range(1, w.count(e, f"{side}.patches") + 1):
            p = f"{side}.patches.{i}."
            print(f"{side} patch {i}: N = {w.number(e, p + 'normal_force') / 1e3:.3f} kN, "
                  f"contact angle {math.degrees(w.number(e, p + 'angle')):.3f} deg, "
                  f"area {w.number(e, p + 'area') * 1e6:.2f} mm2, pmax {w.number(e, p + 'pmax') / 1e6:.1f} MPa")
    for name, h in (("wrc_result_free", e), ("wrc_wheelset_free", ws), ("wrc_profile_free", rail),
                    ("wrc_profile_free", wheel)):
        w.call(name, h)


if __name__ == "__main__":
    main()
