#!/usr/bin/env python3
"""The paper's wheelset with the Python package wrc (docs/python.md): the same study as paper_equilibrium.py (ctypes
over the C API) in the package's terms, printing the same lines.

S1002 wheels on 60E1 rails (1:40, gauge 1435 mm, r0 = 450 mm): the static equilibrium at y = 3 mm under
Q = 200 kN. Prints Y/Q, z, roll and each contact patch (normal force, contact angle, area, peak pressure).

    PYTHONPATH=build/python /usr/bin/python3 examples/python/paper_equilibrium_package.py
"""
import math

import wrc

ws = wrc.wheelset(wheel=wrc.profile.load("profiles/s1002.lua"), rail=wrc.profile.load("profiles/60e1.lua"),
                  gauge=1.435, cant=0.025, radius=0.45)
e = ws.equilibrium(y=3e-3, yaw=0, Q=200e3, grids=False)
print(f"wrc {wrc.__version__}, equilibrium at y = 3 mm, Q = 200 kN")
print(f"Y/Q = {e.Y_Q:.6f}")
print(f"z = {e.z * 1e3:.6f} mm")
print(f"roll = {e.roll * 1e3:.6f} mrad")
for side in ("left", "right"):
    for i, p in enumerate(e[side].patches, start=1):
        print(f"{side} patch {i}: N = {p.normal_force / 1e3:.3f} kN, contact angle {math.degrees(p.angle):.3f} deg, "
              f"area {p.area * 1e6:.2f} mm2, pmax {p.pmax / 1e6:.1f} MPa")
