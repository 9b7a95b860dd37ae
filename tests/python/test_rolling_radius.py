"""Where a rolling wheel's rigid slip is taken (docs/validation.md, "The rolling radius"), against an exact solution.

A disc turning at omega with a deformation steady in space: the particle with reference position (r, theta) is at
(r + u_r) e_r + u_theta e_theta, so on the surface (r = R) it moves along the deformed surface at
    omega (R + u_r + d u_theta / d theta) = omega R (1 + e),   e = (u_r + d u_theta / d theta) / R the hoop strain.
A half-space contact model adds the strain of a flat surface, e_hs = -(1 + nu)(1 - 2 nu) p / E (plane strain), to
the rigid velocity omega x (X - centre) at a reference point X: on the undeformed surface (R) or midway between the
undeformed surfaces (R + u_r, u_r < 0 the compression). Michell's series solution of a disc pressed by a Hertzian
pressure (plane strain) gives e = e_hs exactly when the pressure is balanced on the opposite side (two cylinders
pressed together), and e = e_hs + (1 + nu) P / (2 pi E R) when a centre force balances it (a disc on its axle): the
compression u_r / R is already in e_hs, and 'midway' counts it twice. Then the engine: a cylindrical wheel of radius
r0 turning at V / r0 on a rail of the same material rolls freely (no rigid slip, no creep force) by default."""
import math

import numpy as np
import pytest

from test_wheelset import hertz_pair

E, NU, R = 2.1e11, 0.3, 0.45
MU = E / (2 * (1 + NU))
KAPPA = 3 - 4 * NU


def disc_surface(P, opposite, thetas, M=2 ** 18):
    """Hoop strain e (from the displacements) and u_r / R at r = R, theta in thetas, of a disc under the Hertz
    pressure of load P (N/m) at theta = 0 and either the same pressure at theta = pi or a force P at the centre."""
    a = math.sqrt(4 * P * R / (math.pi * E / (2 * (1 - NU ** 2))))
    p0 = 2 * P / (math.pi * a)
    th = 2 * np.pi * np.arange(M) / M
    s = R * np.where(th > np.pi, th - 2 * np.pi, th) / a
    c = np.fft.rfft(np.where(np.abs(s) < 1, p0 * np.sqrt(np.clip(1 - s * s, 0, None)), 0.0)).real * 2 / M
    c[0] /= 2
    n = np.arange(len(c), dtype=float)
    sig = -c * (1 + (-1.0) ** n) if opposite else -c  # sigma_rr(R) per harmonic
    ur = np.full_like(thetas, (KAPPA - 1) * sig[0] / 2 * R / (2 * MU))  # n = 0: phi = a0 r^2
    dut = np.zeros_like(thetas)
    k = slice(2, None)  # n >= 2: phi = A r^n cos + B r^(n+2) cos, shear-free on r = R
    nn = n[k]
    b = R * sig[k] / (2 * (nn + 1))  # B R^(n+1)
    an = -b * (nn + 1) / (nn - 1)  # A R^(n-1)
    cos = np.cos(np.outer(thetas, nn))
    ur += cos @ ((-nn * an + (KAPPA - nn - 1) * b) / (2 * MU))
    dut += cos @ (nn * (nn * an + (KAPPA + nn + 1) * b) / (2 * MU))
    if not opposite:  # n = 1: Kelvin's force P at the centre (toward the contact) + phi = Bq r^3 cos theta
        cK = P / (8 * math.pi * MU * (1 - NU))
        Bq = -(KAPPA - 1) * P / (2 * math.pi * (1 + KAPPA)) / (2 * R * R)

        def u_theta(t):
            ux = cK * (-(3 - 4 * NU) * math.log(R) + np.cos(t) ** 2)
            return -ux * np.sin(t) + cK * np.cos(t) ** 2 * np.sin(t) + Bq * (KAPPA + 2) * R * R * np.sin(t) / (2 * MU)
        ux = cK * (-(3 - 4 * NU) * math.log(R) + np.cos(thetas) ** 2)
        ur += ux * np.cos(thetas) + cK * np.cos(thetas) * np.sin(thetas) ** 2
        ur += Bq * (KAPPA - 2) * R * R * np.cos(thetas) / (2 * MU)
        h = 1e-6
        dut += (u_theta(thetas + h) - u_theta(thetas - h)) / (2 * h)
    x = R * thetas
    e_hs = -(1 + NU) * (1 - 2 * NU) * p0 * np.sqrt(np.clip(1 - (x / a) ** 2, 0, None)) / E
    return (ur + dut) / R, e_hs, ur / R, a


@pytest.mark.parametrize("P", [2e6, 1e7])
def test_disc_surface_moves_at_its_undeformed_radius_times_the_half_space_strain(P):
    a = math.sqrt(4 * P * R / (math.pi * E / (2 * (1 - NU ** 2))))
    thetas = np.array([0.0, 0.3, 0.6]) * a / R
    e, e_hs, ur, _ = disc_surface(P, True, thetas)
    # the series against the closed form of the approach of a disc's two Hertzian contacts (plane strain)
    assert -2 * ur[0] * R == pytest.approx(2 * P * (1 - NU ** 2) / (math.pi * E) * (2 * math.log(4 * R / a) - 1),
                                           rel=2e-3)
    assert np.all(np.abs(e - e_hs) < 1e-3 * np.abs(e_hs))  # exact (series truncation only)
    assert np.all(ur < -4e-5)  # the compression 'midway' would add is 4-15 % of e_hs here
    e, e_hs, ur, _ = disc_surface(P, False, thetas)  # on its axle: a global stretch, no compression term
    global_term = (1 + NU) * P / (2 * math.pi * E * R)
    assert np.allclose(e - e_hs, global_term, rtol=0.02)
    assert np.all(np.abs(ur) > 5 * global_term)


def test_cylindrical_wheel_at_its_radius_rolls_freely():
    r0, V = 0.45, 20.0
    ws = hertz_pair(R=0.3, r0=r0)
    free = ws.contact(z=-50e-6, V=V, omega=V / r0, mu=0.3).left.patches[0]
    inside = free.pressure > 0
    assert free.creepage.xi == pytest.approx(0, abs=1e-12)
    assert np.abs(free.rigid_slip_x[inside]).max() / V < 1e-8  # along the contact surface, across the patch
    braking = ws.contact(z=-50e-6, V=V, omega=V / r0 * (1 - 1e-5), mu=0.3).left.patches[0]
    assert braking.Fx < -20  # the force of xi = 1e-5, against which free rolling's is measured
    assert abs(free.Fx) < 0.1 * abs(braking.Fx)
    mid = ws.contact(z=-50e-6, V=V, omega=V / r0, mu=0.3, slip_reference="deformed").left.patches[0]
    h0 = free.h.max()
    assert mid.creepage.xi == pytest.approx(h0 / (2 * r0), rel=0.02)  # midway: braking by the compression
