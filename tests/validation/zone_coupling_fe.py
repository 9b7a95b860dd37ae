#!/usr/bin/python3
"""Elastic coupling of contact zones across the turn of a rail head: a finite-element reference.

A study, not a test (not run by ctest). Run from the repository root:

    nice -n 10 /usr/bin/python3 tests/validation/zone_coupling_fe.py          # about 6 minutes on one core
    nice -n 10 /usr/bin/python3 tests/validation/zone_coupling_fe.py --quick  # the coarse mesh alone

Question (docs/validation.md, "Against CONTACT", y = 6.3 mm): S1002 on 60E1 touches in three zones, flange root,
tread (~15 mm along the rail's surface, its normal turned ~20 deg) and crown. wrc solved zones whose normals differ by
more than merge_angle apart (no elastic coupling; 0.26 rad then, 1.2 rad on the conformal surface since this study);
CONTACT couples them through one flat half-space laid along its curved reference surface (Boussinesq at the distance
along the surface). Which is closer to the real bodies?

What it computes:
1. The two bodies near the contact as linear-elastic prisms (E = 2 G (1 + nu), G = 82 GPa, nu = 0.28 as in the
   comparison): the rail head (the 60E1 of profiles/60e1.lua, re-implemented here: R300, R80, R13 arcs, 1:20 flanks,
   cut at a depth with that face fixed) and the wheel as the material on the other side of the same surface (the
   two surfaces are within a fraction of a millimetre of each other between the zones), cut at a height (fixed) and
   with a flange down the gauge face. Both are prisms along the track x (the wheel's 460 mm radius is left out).
   A prism is solved exactly along x by Fourier modes: a load p(x, s) even in x is a cosine integral over the
   wavenumber k, and each k is a 2-D finite-element problem on the cross-section with three displacement components
   (u_x ~ sin kx, u_y, u_z ~ cos kx; quadratic triangles, a graded mesh made here, fine at the zones).
2. Each zone loaded by a Hertz pressure of its own semi-axes; the 3 x 3 zone compliance C_ij = integral of zone i's
   normalised pressure times the normal displacement (along zone i's own normal) that a unit load of zone j's shape
   causes, summed over both bodies. By Parseval C_ij = (1 / pi) int_0^inf f_i(k)^T K(k)^-1 f_j(k) dk.
3. The same matrix for a flat half-space: (a) as CONTACT, Boussinesq at the distance along the surface, no
   projection; (b) at the 3-D distance, projected onto the receiving zone's normal (cos of the turn; the tangential
   Boussinesq displacements of two bodies of one material cancel in the gap).
4. The load split at a fixed total load: each zone P_i = K_i max(0, g_i + D - sum_j E_ij P_j)^1.5 with g_i the
   undeformed overlaps of the case (0.115, 0.035, 0.010 mm), K_i calibrated on wrc's own uncoupled solution of the case
   (84.73, 15.30, 1.08 kN) and E the coupling: zero (wrc then), the half-space's off-diagonal terms (CONTACT's grouping and
   all coupled), or the finite elements' (off-diagonal terms, and on the diagonal the difference between the finite
   element's and the half-space's self compliance). A constant added to all of E moves D only, so the split does not
   depend on the far boundary's constant.
5. Checks of the finite elements: a flat block under a Hertz pressure against Boussinesq's surface displacement
   (differences between two surface points, which drop the fixed far face's constant), the zone model against wrc's
   merged solution, and mesh convergence over three meshes (each halving the element size at the zones).
Units: mm, N, MPa.
"""
import sys
import time

import numpy as np
import scipy.sparse as sps
import scipy.sparse.linalg as spla
import scipy.special as ssp
from scipy.spatial import Delaunay, cKDTree

G_MOD = 82e3                       # MPa, as in the CONTACT comparison
NU = 0.28
E_MOD = 2 * G_MOD * (1 + NU)
E_STAR = E_MOD / (2 * (1 - NU**2))  # both bodies: u = 1 / (pi E*) int p / r
CANT = np.arctan(1 / 40)

# ---------------------------------------------------------------- 60E1 (profiles/60e1.lua, mm, rail frame, z up)


def rail_60e1(depth, step=0.05):
    """Points (y, z) from the gauge flank at `depth` below the top to the field flank, and their arc length s
    (0 at the crown's centre, < 0 on the gauge side). The flanks continue at 1:20 below 36 mm when asked."""
    R1, R2, R3 = 300.0, 80.0, 13.0
    y12, y23 = 10.228, 26.0265
    c1 = np.array([0.0, R1])
    t12 = np.array([y12, R1 - np.sqrt(R1**2 - y12**2)])
    toward = lambda c, t, rf, rt: c + (rf - rt) / rf * (t - c)
    c2 = toward(c1, t12, R1, R2)
    t23 = np.array([y23, c2[1] - np.sqrt(R2**2 - (y23 - c2[0])**2)])
    c3 = toward(c2, t23, R2, R3)
    fl = np.arctan(1 / 20)
    t34 = np.array([c3[0] + R3 * np.cos(fl), c3[1] - R3 * np.sin(fl)])
    yend = t34[0] + (depth - t34[1]) / 20
    ang = lambda c, p: np.arctan2(p[0] - c[0], c[1] - p[1])
    arcs = [(c1, R1, 0.0, ang(c1, t12)), (c2, R2, ang(c2, t12), ang(c2, t23)), (c3, R3, ang(c3, t23), ang(c3, t34))]
    ys, zs = [np.zeros(1)], [np.zeros(1)]
    for c, r, a0, a1 in arcs:
        a = np.linspace(a0, a1, max(2, int(np.ceil(r * (a1 - a0) / step)) + 1))[1:]
        ys.append(c[0] + r * np.sin(a))
        zs.append(c[1] - r * np.cos(a))
    n = max(2, int(np.ceil(np.hypot(yend - t34[0], depth - t34[1]) / step)) + 1)
    ys.append(np.linspace(t34[0], yend, n)[1:])
    zs.append(np.linspace(t34[1], depth, n)[1:])
    hy, hz = np.concatenate(ys), -np.concatenate(zs)           # right half, z up
    y = np.concatenate([-hy[:0:-1], hy])
    z = np.concatenate([hz[:0:-1], hz])
    ds = np.hypot(np.diff(y), np.diff(z))
    s = np.concatenate([[0], np.cumsum(ds)])
    s -= s[len(hy) - 1]
    return y, z, s


def surface_frame(y, z, s, s0):
    """Point, inward normal of the rail (into the head) and contact angle at arc length s0."""
    p = np.array([np.interp(s0, s, y), np.interp(s0, s, z)])
    i = np.clip(np.searchsorted(s, s0), 1, len(s) - 1)
    t = np.array([y[i] - y[i - 1], z[i] - z[i - 1]])
    t /= np.hypot(*t)
    n_in = np.array([t[1], -t[0]])                               # s grows toward +y: inward is the right turn
    return p, n_in


def zones_on_rail(y, z, s, track_y):
    """Arc lengths of the surface points at the given track y (mm): the rail canted 1:40 toward the track centre,
    its gauge face 14 mm below the top of the canted head at track y 717.5 mm (gauge 1435 mm)."""
    cg, sg = np.cos(CANT), np.sin(CANT)
    Y = y * cg - z * sg                 # rail frame to track, rail centre at Y = 0 before the shift
    Z = y * sg + z * cg
    ztop = Z.max()
    gauge = s < 0
    Yg = np.interp(ztop - 14.0, Z[gauge][::-1] if Z[gauge][0] > Z[gauge][-1] else Z[gauge],
                   Y[gauge][::-1] if Z[gauge][0] > Z[gauge][-1] else Y[gauge])
    shift = 717.5 - Yg
    top = Z > ztop - 12.0                # the head's upper surface (single-valued in Y there)
    return [float(np.interp(ty - shift, Y[top], s[top])) for ty in track_y], shift


# ---------------------------------------------------------------- meshing (a DistMesh-like graded triangulation)


def polygon_sdf(poly, fine=0.02):
    """Signed distance (< 0 inside) to a closed counter-clockwise polygon, from a dense resampling of its edges."""
    pts, nrm = [], []
    P = np.vstack([poly, poly[:1]])
    for a, b in zip(P[:-1], P[1:]):
        L = np.hypot(*(b - a))
        m = max(1, int(np.ceil(L / fine)))
        t = (np.arange(m) + 0.5) / m
        pts.append(a + t[:, None] * (b - a))
        d = (b - a) / L
        nrm.append(np.tile([d[1], -d[0]], (m, 1)))   # outward for counter-clockwise
    pts, nrm = np.vstack(pts), np.vstack(nrm)
    tree = cKDTree(pts)

    def sdf(p):
        d, i = tree.query(p, k=3)
        sgn = np.sign(np.einsum('nkj,nkj->nk', p[:, None, :] - pts[i], nrm[i]).sum(axis=1))
        sgn[sgn == 0] = 1
        return sgn * d[:, 0]
    return sdf


def resample_boundary(poly, fh):
    """Boundary nodes along the closed polygon at the local size fh, one snapped to each sharp corner."""
    P = np.vstack([poly, poly[:1]])
    seg_len = np.hypot(*np.diff(P, axis=0).T)
    # walk along the polygon, stepping by fh
    cum = np.concatenate([[0], np.cumsum(seg_len)])
    total = cum[-1]
    t, pos = 0.0, []
    while t < total - 1e-9:
        pos.append(t)
        p = np.array([np.interp(t, cum, P[:, 0]), np.interp(t, cum, P[:, 1])])
        t += float(fh(p[None])[0])
    pos = np.array(pos)
    # snap the nearest sample to each sharp corner (turn > 30 deg)
    d0 = np.diff(P[:-1], axis=0, prepend=P[-2:-1])
    d1 = np.diff(P, axis=0)
    turn = np.abs(np.arctan2(d0[:, 0] * d1[:, 1] - d0[:, 1] * d1[:, 0], (d0 * d1).sum(1)))
    for c in np.nonzero(turn > np.radians(30))[0]:
        j = np.argmin(np.abs(pos - cum[c]))
        pos[j] = cum[c]
    pos = np.unique(pos)
    return np.column_stack([np.interp(pos, cum, P[:, 0]), np.interp(pos, cum, P[:, 1])])


def distmesh(poly, fh, hmin, iters=120):
    """Graded triangle mesh of a polygon: fixed boundary nodes at the local size, interior nodes relaxed by
    Persson and Strang's truss analogy (DistMesh), retriangulated by Delaunay."""
    sdf = polygon_sdf(poly)
    pfix = resample_boundary(poly, fh)
    lo, hi = poly.min(0), poly.max(0)
    # initial interior points: a hexagonal lattice at hmin, thinned to the density 1 / h^2
    xs = np.arange(lo[0], hi[0], hmin)
    ys = np.arange(lo[1], hi[1], hmin * np.sqrt(3) / 2)
    X, Y = np.meshgrid(xs, ys)
    X[1::2] += hmin / 2
    p = np.column_stack([X.ravel(), Y.ravel()])
    p = p[sdf(p) < -0.5 * hmin]
    rng = np.random.default_rng(1)
    keep = rng.random(len(p)) < (hmin / fh(p))**2
    p = p[keep]
    p = p[sdf(p) < -0.5 * fh(p)]
    nf = len(pfix)
    p = np.vstack([pfix, p])
    old = np.inf
    for it in range(iters):
        if it == 0 or np.max(np.hypot(*(p - old).T)) > 0.1 * hmin:
            old = p.copy()
            tri = Delaunay(p).simplices
            c = p[tri].mean(1)
            tri = tri[sdf(c) < -1e-3 * hmin]
            e = np.vstack([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]])
            e = np.unique(np.sort(e, axis=1), axis=0)
        bv = p[e[:, 0]] - p[e[:, 1]]
        L = np.hypot(*bv.T)
        hb = fh((p[e[:, 0]] + p[e[:, 1]]) / 2)
        L0 = hb * 1.2 * np.sqrt((L**2).sum() / (hb**2).sum())
        F = np.maximum(L0 - L, 0)
        Fv = (F / L)[:, None] * bv
        Ft = np.zeros_like(p)
        np.add.at(Ft, e[:, 0], Fv)
        np.add.at(Ft, e[:, 1], -Fv)
        Ft[:nf] = 0
        p = p + 0.2 * Ft
        d = sdf(p[nf:])
        out = d > -0.2 * fh(p[nf:])
        if out.any():   # pull escaping interior nodes back inside, along the distance gradient
            q = p[nf:][out]
            eps = 1e-4
            gx = (sdf(q + [eps, 0]) - d[out]) / eps
            gy = (sdf(q + [0, eps]) - d[out]) / eps
            q -= ((d[out] + 0.2 * fh(q)) / np.maximum(gx**2 + gy**2, 1e-12))[:, None] * np.column_stack([gx, gy])
            p[nf:][out] = q
    tri = Delaunay(p).simplices
    tri = tri[sdf(p[tri].mean(1)) < -1e-3 * hmin]
    # drop nodes no triangle uses, orient counter-clockwise
    used = np.unique(tri)
    remap = -np.ones(len(p), int)
    remap[used] = np.arange(len(used))
    p, tri = p[used], remap[tri]
    a = p[tri]
    area = 0.5 * ((a[:, 1, 0] - a[:, 0, 0]) * (a[:, 2, 1] - a[:, 0, 1]) - (a[:, 2, 0] - a[:, 0, 0]) * (a[:, 1, 1] - a[:, 0, 1]))
    tri[area < 0] = tri[area < 0][:, [0, 2, 1]]
    # drop the slivers Delaunay leaves between nearly collinear boundary nodes (a gap of ~zero area)
    edges2 = sum(((a[:, i] - a[:, (i + 1) % 3])**2).sum(1) for i in range(3))
    good = 4 * np.sqrt(3) * np.abs(area) / edges2 > 0.05
    tri = tri[good]
    used = np.unique(tri)
    remap = -np.ones(len(p), int)
    remap[used] = np.arange(len(used))
    return p[used], remap[tri]


def to_quadratic(p, tri):
    """T3 to T6: midside nodes (straight sides). Returns nodes, elements (corners 0-2, midsides 3: 0-1, 4: 1-2,
    5: 2-0)."""
    e = np.vstack([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]])
    es = np.sort(e, axis=1)
    uniq, inv = np.unique(es, axis=0, return_inverse=True)
    mid = p[uniq].mean(1)
    nt = len(tri)
    tri6 = np.column_stack([tri, len(p) + inv[:nt], len(p) + inv[nt:2 * nt], len(p) + inv[2 * nt:]])
    return np.vstack([p, mid]), tri6


# ---------------------------------------------------------------- 2.5-D finite elements


def shape_t6(r, s):
    L1, L2, L3 = 1 - r - s, r, s
    N = np.array([L1 * (2 * L1 - 1), L2 * (2 * L2 - 1), L3 * (2 * L3 - 1), 4 * L1 * L2, 4 * L2 * L3, 4 * L3 * L1])
    dNr = np.array([-(4 * L1 - 1), 4 * L2 - 1, 0 * r, 4 * (L1 - L2), 4 * L3, -4 * L3])
    dNs = np.array([-(4 * L1 - 1), 0 * r, 4 * L3 - 1, -4 * L2, 4 * L2, 4 * (L1 - L3)])
    return N, dNr, dNs


def tri_rule6():
    a, b = 0.445948490915965, 0.091576213509771
    w1, w2 = 0.223381589678011, 0.109951743655322
    r = np.array([a, 1 - 2 * a, a, b, 1 - 2 * b, b])
    s = np.array([a, a, 1 - 2 * a, b, b, 1 - 2 * b])
    return r, s, np.array([w1] * 3 + [w2] * 3) / 2


def elasticity_d():
    lam = E_MOD * NU / ((1 + NU) * (1 - 2 * NU))
    D = np.zeros((6, 6))
    D[:3, :3] = lam
    D[np.arange(3), np.arange(3)] += 2 * G_MOD
    D[np.arange(3, 6), np.arange(3, 6)] = G_MOD
    return D


def assemble(nodes, el):
    """K(k) = K0 + k K1 + k^2 K2 for modes u_x = U_x sin kx, (u_y, u_z) = (U_y, U_z) cos kx.
    Strains [exx, eyy, ezz, gyz, gxy, gxz] = (B0 + k B1) U."""
    r, s, w = tri_rule6()
    N, dNr, dNs = shape_t6(r, s)                    # (6 nodes, nq)
    X = nodes[el]                                    # (ne, 6, 2)
    J11 = np.einsum('aq,ea->eq', dNr, X[:, :, 0]); J12 = np.einsum('aq,ea->eq', dNr, X[:, :, 1])
    J21 = np.einsum('aq,ea->eq', dNs, X[:, :, 0]); J22 = np.einsum('aq,ea->eq', dNs, X[:, :, 1])
    det = J11 * J22 - J12 * J21
    if (det <= 0).any():
        raise RuntimeError("inverted element in the mesh")
    dNy = (J22[:, None] * dNr[None] - J12[:, None] * dNs[None]) / det[:, None]   # (ne, 6, nq)
    dNz = (-J21[:, None] * dNr[None] + J11[:, None] * dNs[None]) / det[:, None]
    ne, nq = det.shape
    B0 = np.zeros((ne, nq, 6, 18)); B1 = np.zeros((ne, nq, 6, 18))
    ux, uy, uz = np.arange(6) * 3, np.arange(6) * 3 + 1, np.arange(6) * 3 + 2
    tq = lambda a: np.transpose(a, (0, 2, 1))
    B1[:, :, 0, ux] = N.T[None]
    B0[:, :, 1, uy] = tq(dNy)
    B0[:, :, 2, uz] = tq(dNz)
    B0[:, :, 3, uy] = tq(dNz); B0[:, :, 3, uz] = tq(dNy)
    B0[:, :, 4, ux] = tq(dNy); B1[:, :, 4, uy] = -N.T[None]
    B0[:, :, 5, ux] = tq(dNz); B1[:, :, 5, uz] = -N.T[None]
    D = elasticity_d()
    wq = det * w[None]                                        # (ne, nq)
    DB0 = np.einsum('ij,eqjk->eqik', D, B0); DB1 = np.einsum('ij,eqjk->eqik', D, B1)
    k00 = np.einsum('eq,eqia,eqib->eab', wq, B0, DB0)
    k01 = np.einsum('eq,eqia,eqib->eab', wq, B0, DB1)
    k11 = np.einsum('eq,eqia,eqib->eab', wq, B1, DB1)
    dof = (3 * el[:, :, None] + np.arange(3)[None, None]).reshape(ne, 18)
    I = np.repeat(dof, 18, axis=1).ravel(); Jc = np.tile(dof, (1, 18)).ravel()
    n = 3 * len(nodes)
    mk = lambda k: sps.csr_matrix((k.ravel(), (I, Jc)), shape=(n, n))
    K01 = mk(k01)
    return mk(k00), K01 + K01.T, mk(k11)


def boundary_edges(el):
    """Quadratic boundary edges (corner, corner, midside) of a T6 mesh."""
    sides = [(0, 1, 3), (1, 2, 4), (2, 0, 5)]
    e = np.vstack([el[:, list(sd)] for sd in sides])
    key = np.sort(e[:, :2], axis=1)
    _, idx, cnt = np.unique(key, axis=0, return_index=True, return_counts=True)
    return e[idx[cnt == 1]]


class Body:
    """One prismatic body: mesh, K0/K1/K2, fixed dofs, and its loaded surface (edges with arc length s)."""

    def __init__(self, name, poly, fixed_pred, surf_y, surf_z, surf_s, fh, hmin, inward_sign):
        t0 = time.time()
        p, tri = distmesh(poly, fh, hmin)
        self.nodes, self.el = to_quadratic(p, tri)
        self.name = name
        self.K = assemble(self.nodes, self.el)
        edges = boundary_edges(self.el)
        mid = self.nodes[edges[:, 2]]
        # surface edges: the midside node lies on the rail's surface polyline
        tree = cKDTree(np.column_stack([surf_y, surf_z]))
        d, i = tree.query(mid)
        # (the polyline's points lie 0.05 mm apart, a chord's midpoint within 0.03 mm of one; other faces' edges
        # meet the surface only at the far corners, where no zone loads it)
        on = d < 0.06
        self.surf = edges[on]
        # arc length of surface points: their projection on the polyline's nearest segments
        P = np.column_stack([surf_y, surf_z])

        def s_of(q):
            i = np.clip(tree.query(q)[1], 1, len(P) - 2)
            best_d, best_s = np.full(len(q), np.inf), np.zeros(len(q))
            for j0 in (i - 1, i):
                a, b = P[j0], P[j0 + 1]
                ab = b - a
                tt = np.clip(((q - a) * ab).sum(1) / (ab * ab).sum(1), 0, 1)
                dd = np.hypot(*(a + tt[:, None] * ab - q).T)
                ss = surf_s[j0] + tt * (surf_s[j0 + 1] - surf_s[j0])
                better = dd < best_d
                best_d[better], best_s[better] = dd[better], ss[better]
            return best_s
        self.s_of = s_of
        self.inward_sign = inward_sign          # +1: the rail's inward normal is this body's inward normal
        fx = fixed_pred(self.nodes)
        free = np.ones(3 * len(self.nodes), bool)
        free[np.repeat(np.nonzero(fx)[0] * 3, 3) + np.tile(np.arange(3), fx.sum())] = False
        self.free = np.nonzero(free)[0]
        self.ndof = 3 * len(self.nodes)
        self.t_mesh = time.time() - t0

    def load_vectors(self, k, zones):
        """Consistent nodal loads of each zone's unit-load Hertz pressure in mode k (columns)."""
        g = np.polynomial.legendre.leggauss(6)
        xi, wg = (g[0] + 1) / 2, g[1] / 2
        Nq = np.array([(1 - xi) * (1 - 2 * xi), xi * (2 * xi - 1), 4 * xi * (1 - xi)])    # corner a, b, mid
        dNq = np.array([4 * xi - 3, 4 * xi - 1, 4 - 8 * xi])
        X = self.nodes[self.surf]                          # (ns, 3, 2)
        pts = np.einsum('aq,eaj->eqj', Nq, X)
        tan = np.einsum('aq,eaj->eqj', dNq, X)
        jac = np.hypot(tan[..., 0], tan[..., 1])
        s = self.s_of(pts.reshape(-1, 2)).reshape(pts.shape[:2])
        F = np.zeros((self.ndof, len(zones)))
        for c, zn in enumerate(zones):
            w = hertz_hat(k, s, zn)                       # (ns, nq) per unit length of s
            if k == 0:   # every zone's unit load must be on the mesh's surface edges
                total = (w * jac * wg[None]).sum()
                if abs(total - 1) > 5e-3:
                    raise RuntimeError(f"{self.name}: zone {zn['name']} carries {total:.4f} of its unit load on the mesh")
            # the pressure acts along the rail's inward normal (the wheel: the opposite, its own inward normal)
            nvec = self.inward_sign * zn['n_in']
            for a in range(3):
                f = (Nq[a][None] * w * jac * wg[None]).sum(1)
                for j in range(2):
                    np.add.at(F[:, c], 3 * self.surf[:, a] + 1 + j, f * nvec[j])
        return F

    def compliance(self, ks, zones, rail=None):
        """C[q] = F^T K(k_q)^-1 F for each k in ks (3-D: u_y, u_z in each zone's normal direction); with the rail's
        (y, z, s), also the surface's displacement along the rail's inward normal (this body's share of the gap's
        closing) at x = 0 under zone 0's unit load, at the surface nodes (s, u_n(k_q))."""
        K0, K1, K2 = self.K
        fr = self.free
        out, un = [], []
        if rail is not None:
            sn = np.unique(self.surf.ravel())
            s_n = self.s_of(self.nodes[sn])
            o = np.argsort(s_n)
            sn, s_n = sn[o], s_n[o]
            nrm = np.array([surface_frame(*rail, v)[1] for v in s_n])
        for k in ks:
            Kk = (K0 + k * K1 + k * k * K2)[fr][:, fr].tocsc()
            F = self.load_vectors(k, zones)[fr]
            U = spla.splu(Kk, permc_spec='COLAMD').solve(F)
            out.append(F.T @ U)
            if rail is not None:
                Uf = np.zeros(self.ndof)
                Uf[fr] = U[:, 0]
                un.append(self.inward_sign * (nrm[:, 0] * Uf[3 * sn + 1] + nrm[:, 1] * Uf[3 * sn + 2]))
        if rail is None:
            return np.array(out)
        return np.array(out), (s_n, np.array(un))


def hertz_hat(k, s, zn):
    """Cosine transform along x of a unit-load Hertz pressure (semi-axes a along x, b along s, centred at s0):
    int w(x, s) cos(kx) dx = 3 c J1(kc) / (2 a^2 b k), c = a sqrt(1 - ((s - s0) / b)^2)."""
    a, b = zn['a'], zn['b']
    t = (s - zn['s0']) / b
    c = a * np.sqrt(np.clip(1 - t * t, 0, None))
    if k == 0:
        return 3 * c * c / (4 * a * a * b)
    return 3 * c * ssp.j1(k * c) / (2 * a * a * b * k)


def k_grid(n):
    """Wavenumbers (1/mm) and weights for int_0^inf dk: k = 0 and a geometric grid from 1e-3 to 20 (n odd), Simpson's
    rule in ln k (the integrand times k is smooth there) plus a trapezoid on [0, 1e-3]."""
    n += 1 - n % 2
    kk = np.geomspace(1e-3, 20.0, n)
    h = np.log(kk[1] / kk[0])
    ws = np.ones(n)
    ws[1:-1:2], ws[2:-1:2] = 4, 2
    w = ws * h / 3 * kk
    return np.concatenate([[0.0], kk]), np.concatenate([[kk[0] / 2], w + np.eye(n)[0] * kk[0] / 2])


# ---------------------------------------------------------------- half-space references


def hs_self(zn):
    """Pressure-weighted mean displacement of a unit-load Hertz pressure on an elliptic patch, both bodies:
    (0.3 / (pi E*)) int_0^2pi dth / sqrt(a^2 cos^2 + b^2 sin^2) (0.6 / (a E*) on a circle, Hertz)."""
    th = np.linspace(0, 2 * np.pi, 4001)[:-1]
    return 0.3 / (np.pi * E_STAR) * np.mean(1 / np.sqrt((zn['a'] * np.cos(th))**2 + (zn['b'] * np.sin(th))**2)) * 2 * np.pi


def ellipse_quadrature(zn, n=24):
    """Points (x, s) and weights of a unit-load Hertz pressure on its ellipse (rho = sin phi: smooth integrand)."""
    g, wg = np.polynomial.legendre.leggauss(n)
    phi = (g + 1) * np.pi / 4
    wphi = wg * np.pi / 4
    th = (np.arange(2 * n) + 0.5) * np.pi / n
    rho = np.sin(phi)
    wr = np.sin(phi) * np.cos(phi)**2 * wphi            # rho sqrt(1 - rho^2) drho
    R, T = np.meshgrid(rho, th, indexing='ij')
    W = np.outer(wr, np.full(len(th), np.pi / n))
    W /= W.sum()
    return zn['a'] * R * np.cos(T), zn['s0'] + zn['b'] * R * np.sin(T), W


def hs_coupling(zi, zj, rail, mode):
    """Mean displacement over zone i's pressure of a unit load of zone j's shape, both bodies.
    mode 'surface': flat half-space at the distance along the surface (CONTACT); 'chord': at the 3-D distance,
    projected on zone i's normal."""
    xi, si, wi = ellipse_quadrature(zi)
    xj, sj, wj = ellipse_quadrature(zj)
    if mode == 'surface':
        r = np.sqrt((xi.ravel()[:, None] - xj.ravel()[None])**2 + (si.ravel()[:, None] - sj.ravel()[None])**2)
        proj = 1.0
    else:
        y, z, s = rail
        Pi = np.column_stack([np.interp(si.ravel(), s, y), np.interp(si.ravel(), s, z)])
        Pj = np.column_stack([np.interp(sj.ravel(), s, y), np.interp(sj.ravel(), s, z)])
        d2 = ((Pi[:, None] - Pj[None])**2).sum(-1)
        r = np.sqrt((xi.ravel()[:, None] - xj.ravel()[None])**2 + d2)
        proj = float(zi['n_in'] @ zj['n_in'])
    return proj * (wi.ravel()[:, None] * wj.ravel()[None] / r).sum() / (np.pi * E_STAR)


# ---------------------------------------------------------------- the zone model


def split(g, Kh, E, total):
    """P_i = K_i max(0, g_i + D - (E P)_i)^1.5 with sum P = total: fixed point on P, bisection on D."""
    P = total * Kh * g**1.5 / (Kh * g**1.5).sum()
    for _ in range(200):
        shift = E @ P

        def load(D):
            return Kh * np.clip(g + D - shift, 0, None)**1.5
        lo, hi = -g.max(), 1.0
        for _ in range(100):
            mid = (lo + hi) / 2
            lo, hi = (mid, hi) if load(mid).sum() < total else (lo, mid)
        Pn = load((lo + hi) / 2)
        if np.max(np.abs(Pn - P)) < 1e-6 * total:
            return Pn
        P = 0.5 * P + 0.5 * Pn
    return P


# ---------------------------------------------------------------- the case

# Undeformed overlaps (mm, brute force at wrc's pose) and wrc's zone forces (N), docs/validation.md "Against
# CONTACT"; CONTACT's split for comparison; wrc with every zone in one area (merge_angle = 1.2).
NAMES = ['flange root', 'tread', 'crown']
G_OVERLAP = np.array([0.115, 0.035, 0.010])
P_WRC = np.array([84.73e3, 15.30e3, 1.08e3])
P_CONTACT = np.array([86.22e3, 11.48e3, 3.33e3])
P_WRC_MERGED = np.array([90.3e3, 9.1e3, 1.6e3])
TRACK_Y = [725.0, 739.0, 762.0]     # track y of the zones (mm); the root: wrc's centre of pressure there
R_WHEEL = 460.0


def hertz_axes(P, g, angle, B=None):
    """Semi-axes of a zone from its load and overlap: A = cos(angle) / 2 R along the track, the equivalent radius
    from P = 4/3 E* sqrt(Re) g^1.5 (Hertz, circular form), B = 1 / (4 Re^2 A), a / b = (B / A)^(2/3) (Greenwood's
    approximation), sqrt(ab) = (3 P Re / 4 E*)^(1/3)."""
    A = np.cos(angle) / (2 * R_WHEEL)
    if B is None:
        Re = (3 * P / (4 * E_STAR * g**1.5))**2
        B = 1 / (4 * Re * Re * A)
        c = (3 * P * Re / (4 * E_STAR))**(1 / 3)
    else:                                   # curvatures given: a b = Re g
        Re = 1 / (2 * np.sqrt(A * B))
        c = np.sqrt(Re * g)
    ratio = (max(A, B) / min(A, B))**(2 / 3)
    a_long, a_short = c * np.sqrt(ratio), c / np.sqrt(ratio)
    return (a_long, a_short) if B > A else (a_short, a_long)


def build_zones(y, z, s, scale_ab=1.0, root_y=None):
    s0s, _ = zones_on_rail(y, z, s, [root_y or TRACK_Y[0]] + TRACK_Y[1:])
    zones = []
    for name, s0, P, g in zip(NAMES, s0s, P_WRC, G_OVERLAP):
        p, n_in = surface_frame(y, z, s, s0)
        angle = np.arctan2(-n_in[0], -n_in[1]) + CANT       # contact angle in the track (canted)
        # the crown's load in wrc is lowered by the tread's coupling: its axes from the curvatures (rail R300,
        # the wheel's tread taken straight across) and its overlap instead
        a, b = hertz_axes(P, g, angle, 1 / 600 if name == 'crown' else None)
        zones.append(dict(name=name, s0=s0, p=p, n_in=n_in, angle=angle, a=a * scale_ab, b=b * scale_ab))
    return zones


def bodies(y, z, s, zones, h0, grade=0.25, hmax=5.0, size=1.0):
    """The rail head (bottom fixed) and the wheel (top fixed), meshed finely at the zones."""
    cut = 36.0 * size
    yr, zr, _ = rail_60e1(cut)
    surfp = np.column_stack([y, z])
    segs = []
    for zn in zones:
        m = np.abs(s - zn['s0']) <= zn['b'] * 1.1
        segs.append(surfp[m])
    tree = cKDTree(np.vstack(segs))

    def fh(q):
        return np.minimum(hmax, h0 + grade * tree.query(q)[0])
    # rail: the profile from the gauge flank's bottom over the crown to the field flank's bottom (both at the
    # cut), closed by the bottom face
    poly_r = np.column_stack([yr, zr])
    fixed_r = lambda q: q[:, 1] < -cut + 1e-6
    rail_body = Body('rail', _ccw(poly_r), fixed_r, y, z, s, fh, h0, +1)
    # wheel: above the same surface, from the gauge flank 20 mm down (its flange) to the field side at y = 25 mm,
    # then off the rail; top fixed at 40 mm above the crown (x size)
    top = 40.0 * size
    m = (z >= -20.0) & (y <= 25.0)
    prof = np.column_stack([y[m], z[m]])
    ye = prof[-1]
    poly_w = np.vstack([prof, [[60.0 * size, ye[1] - 0.05 * (60.0 * size - ye[0])], [60.0 * size, top],
                               [-70.0 * size, top], [-70.0 * size, -20.0]]])
    fixed_w = lambda q: q[:, 1] > top - 1e-6
    wheel_body = Body('wheel', _ccw(poly_w), fixed_w, y, z, s, fh, h0, -1)
    return rail_body, wheel_body


def _ccw(poly):
    area = 0.5 * np.sum(poly[:, 0] * np.roll(poly[:, 1], -1) - np.roll(poly[:, 0], -1) * poly[:, 1])
    return poly if area > 0 else poly[::-1]


# ---------------------------------------------------------------- checks and study


def flat_block_check(h0, nk):
    """A flat block (200 x 100 mm section, bottom fixed) under a unit Hertz load (a = b = 3 mm) against Boussinesq:
    the surface displacement at x = 0 relative to that at 8 mm, and two-zone compliances relative to the self one."""
    W, Dp = 100.0, 100.0
    ys = np.linspace(-W, W, 8001)
    zs = np.zeros_like(ys)
    ss = ys.copy()
    z1 = dict(name='load', s0=0.0, a=3.0, b=3.0, n_in=np.array([0.0, -1.0]))
    z2 = dict(name='far', s0=15.0, a=2.0, b=1.5, n_in=np.array([0.0, -1.0]))
    tree = cKDTree(np.array([[0.0, 0.0], [15.0, 0.0]]))
    fh = lambda q: np.minimum(6.0, h0 + 0.25 * np.maximum(tree.query(q)[0] - 3.0, 0))
    poly = np.array([[-W, -Dp], [W, -Dp], [W, 0.0], [-W, 0.0]])
    body = Body('block', poly, lambda q: q[:, 1] < -Dp + 1e-6, ys, zs, ss, fh, h0, +1)
    ks, wk = k_grid(nk)
    K0, K1, K2 = body.K
    fr = body.free
    # surface displacement at x = 0 of the unit Hertz load of z1 (single body: E* of one body is 2 E_STAR)
    srf = np.unique(body.surf[:, [0, 1, 2]].ravel())
    srf = srf[np.abs(body.nodes[srf, 1]) < 1e-9]
    srf = srf[np.argsort(body.nodes[srf, 0])]
    u = np.zeros(len(srf))
    C = np.zeros((2, 2))
    for k, w in zip(ks, wk):
        Kk = (K0 + k * K1 + k * k * K2)[fr][:, fr].tocsc()
        F = body.load_vectors(k, [z1, z2])
        U = np.zeros((body.ndof, 2))
        U[fr] = spla.splu(Kk, permc_spec='COLAMD').solve(F[fr])
        u += w / np.pi * (-U[3 * srf + 2, 0])
        C += w / np.pi * (F.T @ U)
    y_s = body.nodes[srf, 0]
    # Boussinesq for one body: u = (1 - nu^2) / (pi E) int p / r, by quadrature over the Hertz pressure
    xq, sq, wq = ellipse_quadrature(z1, 40)

    def bous(yy):
        return ((1 - NU**2) / (np.pi * E_MOD) * (wq.ravel()[None] / np.hypot(xq.ravel()[None], sq.ravel()[None] - np.asarray(yy)[:, None])).sum(1))
    ref = 8.0
    rows = []
    for yy in [4.0, 5.0, 6.0, 10.0, 15.0, 20.0, 30.0]:
        fe = np.interp(yy, y_s, u) - np.interp(ref, y_s, u)
        an = bous([yy])[0] - bous([ref])[0]
        rows.append((yy, fe, an))
    one = lambda zz: hs_self(zz) / 2   # one body: E* of one body is 2 E_STAR
    hs12 = hs_coupling(z1, z2, None, "surface") / 2
    fe_rel = C[0, 0] - C[0, 1]
    hs_rel = one(z1) - hs12
    fe_rel2 = C[1, 1] - C[0, 1]
    hs_rel2 = one(z2) - hs12
    return body, rows, (fe_rel, hs_rel, fe_rel2, hs_rel2)


def study(h0, nk, size=1.0, scale_ab=1.0, root_y=None):
    y, z, s = rail_60e1(36.0)
    zones = build_zones(y, z, s, scale_ab, root_y)
    rb, wb = bodies(y, z, s, zones, h0, size=size)
    ks, wk = k_grid(nk)
    C = np.zeros((3, 3))
    per = {}
    for b in (rb, wb):
        Ck, (s_n, un) = b.compliance(ks, zones, (y, z, s))
        Cb = (wk[:, None, None] * Ck).sum(0) / np.pi
        per[b.name] = Cb
        per[b.name + ' profile'] = (s_n, (wk[:, None] * un).sum(0) / np.pi)
        C += Cb
    return zones, (rb, wb), C, per, (y, z, s)


def profile_table(r):
    """The gap's closing at x = 0 along the surface under the root's unit load, relative to the root patch's edge
    toward the tread: finite elements (both bodies) against the flat half-space."""
    zones, (y, z, s), per = r['zones'], r['rail'], r['per']
    root = zones[0]
    edge = root['s0'] + root['b']
    xq, sq, wq = ellipse_quadrature(root, 40)
    P = lambda v: np.column_stack([np.interp(v, s, y), np.interp(v, s, z)])
    n0 = root['n_in']

    def hs(v, mode):
        v = np.atleast_1d(v)
        if mode == 'surface':
            d2 = (v[:, None] - sq.ravel()[None])**2
            proj = 1.0
        else:
            d2 = ((P(v)[:, None] - P(sq.ravel())[None])**2).sum(-1)
            proj = np.array([surface_frame(y, z, s, vv)[1] @ n0 for vv in v])[:, None]
        return (proj * wq.ravel()[None] / np.sqrt(xq.ravel()[None]**2 + d2)).sum(1) / (np.pi * E_STAR)

    def fe(v):
        return sum(np.interp(v, *per[b + ' profile']) for b in ('rail', 'wheel'))
    print(f"   s from the root's centre (mm); tread centre at {zones[1]['s0'] - root['s0']:.2f}, its patch "
          f"{zones[1]['s0'] - zones[1]['b'] - root['s0']:.2f} .. {zones[1]['s0'] + zones[1]['b'] - root['s0']:.2f}")
    print("     s      FE     half-space (surface distance)   (3-D distance, projected)   [1e-9 mm/N]")
    for ds in sorted([root['b'], 4.0, 6.0, 8.0, 10.0, 12.0, zones[1]['s0'] - root['s0'], 16.0, 20.0, 25.0]):
        v = root['s0'] + ds
        f = fe(v) - fe(edge)
        a = hs(v, 'surface')[0] - hs(edge, 'surface')[0]
        c = hs(v, 'chord')[0] - hs(edge, 'chord')[0]
        print(f"   {ds:6.2f} {f * 1e9:9.2f} {a * 1e9:9.2f} ({(a - f) / abs(f) * 100 if f else 0:+6.1f} %)"
              f"           {c * 1e9:9.2f} ({(c - f) / abs(f) * 100 if f else 0:+6.1f} %)")
    # each body alone (twice its share, against the half-space of both) at the tread's centre
    v = zones[1]['s0']
    a = hs(v, 'surface')[0] - hs(edge, 'surface')[0]
    for b in ('rail', 'wheel'):
        f = 2 * (np.interp(v, *per[b + ' profile']) - np.interp(edge, *per[b + ' profile']))
        print(f"     at the tread's centre, the {b} alone (twice its share): {f * 1e9:.2f}, the half-space "
              f"{(a - f) / abs(f) * 100:+.1f} % from it")


def hs_matrix(zones, rail, mode):
    H = np.zeros((3, 3))
    for i in range(3):
        for j in range(3):
            H[i, j] = hs_self(zones[i]) if i == j else hs_coupling(zones[i], zones[j], rail, mode)
    return H


def splits(zones, C, rail):
    g = G_OVERLAP
    Kh = P_WRC / g**1.5
    total = P_WRC.sum()
    Hs = hs_matrix(zones, rail, 'surface')
    Hc = hs_matrix(zones, rail, 'chord')
    off = lambda M: M - np.diag(np.diag(M))
    contact_group = off(Hs) * np.array([[0, 1, 0], [1, 0, 0], [0, 0, 0]])
    tread_crown = off(Hs) * np.array([[0, 0, 0], [0, 0, 1], [0, 1, 0]])
    # Kh is calibrated on wrc's solution, whose tread and crown are coupled: remove that coupling first
    Kh = P_WRC / np.clip(g - tread_crown @ P_WRC, 1e-9, None)**1.5
    fe = C - np.diag(np.diag(Hs))      # the FE's self compliance in excess of the half-space's, and its coupling
    out = {
        'none (wrc, zones apart)': split(g, Kh, tread_crown, total),
        'half-space, root + tread (CONTACT grouping)': split(g, Kh, contact_group + tread_crown, total),
        'half-space along the surface, all coupled': split(g, Kh, off(Hs), total),
        'half-space at 3-D distance, projected': split(g, Kh, off(Hc), total),
        'finite elements': split(g, Kh, fe, total),
    }
    return out, Hs, Hc


def main():
    quick = '--quick' in sys.argv
    t0 = time.time()
    print("Zone coupling across the rail head's turn: 2.5-D finite elements against the flat half-space")
    print(f"E = {E_MOD:.0f} MPa, nu = {NU}, E* (both bodies) = {E_STAR:.0f} MPa\n")
    print("1. Flat block 200 x 100 mm (bottom fixed) under a unit Hertz load a = b = 3 mm: surface displacement at")
    print("   x = 0 relative to that at 8 mm from the centre, finite elements against Boussinesq (1e-9 mm/N)")
    for h0 in ([0.4] if quick else [0.4, 0.2]):
        body, rows, rel = flat_block_check(h0, 24 if quick else 40)
        print(f"   mesh h0 = {h0} mm: {len(body.nodes)} nodes, {body.ndof} dofs")
        for yy, fe, an in rows:
            print(f"     r = {yy:5.1f} mm: FE {fe * 1e9:9.4f}   Boussinesq {an * 1e9:9.4f}   ({(fe - an) / abs(an) * 100 if abs(an) > 0 else 0:+.2f} %)")
        print(f"     zone at 15 mm (2 x 1.5 mm): C11 - C12 FE {rel[0] * 1e9:.4f}, half-space {rel[1] * 1e9:.4f}; "
              f"C22 - C12 FE {rel[2] * 1e9:.4f}, half-space {rel[3] * 1e9:.4f} (1e-9 mm/N)")
    print(f"   ({time.time() - t0:.0f} s)\n")

    # (label, h0 mm, wavenumbers, body size factor, root's track y mm or None, patch axes factor)
    runs = [('mesh 1', 0.4, 25, 1.0, None, 1.0)]
    if not quick:
        runs += [('mesh 2', 0.2, 25, 1.0, None, 1.0), ('mesh 3', 0.1, 25, 1.0, None, 1.0),
                 ('mesh 2, 49 wavenumbers', 0.2, 49, 1.0, None, 1.0),
                 ('mesh 2, bodies x 1.5', 0.2, 25, 1.5, None, 1.0),
                 ('mesh 2, patch axes x 0.75', 0.2, 25, 1.0, None, 0.75),
                 ('mesh 2, root at track y 721 mm', 0.2, 25, 1.0, 721.0, 1.0)]
    results = []
    for label, h0, nk, size, root_y, sab in runs:
        zones, bods, C, per, rail = study(h0, nk, size=size, scale_ab=sab, root_y=root_y)
        results.append(dict(label=label, h0=h0, nk=nk, size=size, zones=zones, bodies=bods, C=C, per=per, rail=rail))
        print(f"   ({label}: {time.time() - t0:.0f} s)", flush=True)
    print()
    pairs = [(0, 1), (0, 2), (1, 2)]

    def rel(M, i, j):
        return M[i, j], M[i, i] - M[i, j], M[j, j] - M[i, j]
    print("2. The zones (60E1 canted 1:40, gauge 1435 mm; semi-axes from each zone's load and overlap, Hertz)")
    for r in results:
        if r['label'] not in ('mesh 1', 'mesh 2, root at track y 721 mm', 'mesh 2, patch axes x 0.75'):
            continue
        zones = r['zones']
        print(f"   {r['label']}:")
        for zn in zones:
            print(f"     {zn['name']:12s} s = {zn['s0']:7.2f} mm along the rail's surface, contact angle "
                  f"{np.degrees(zn['angle']):5.1f} deg, a = {zn['a']:.2f}, b = {zn['b']:.2f} mm")
        d01 = zones[1]['s0'] - zones[0]['s0']
        chord = np.hypot(*(zones[1]['p'] - zones[0]['p']))
        turn = np.degrees(np.arccos(zones[0]['n_in'] @ zones[1]['n_in']))
        print(f"     root to tread: {d01:.2f} mm along the surface, {chord:.2f} mm straight, normals {turn:.1f} deg apart")
    print()
    print("3. Zone compliances, 1e-9 mm/N (both bodies): C_ij = zone i's mean normal displacement per N on zone j.")
    print("   What sets the split are the differences self minus coupling, C_ii - C_ij and C_jj - C_ij")
    print("   (no coupling: C_ij = 0, the differences are the half-space's self compliances)")
    for r in results:
        C, zones, rail = r['C'], r['zones'], r['rail']
        Hs = hs_matrix(zones, rail, 'surface')
        Hc = hs_matrix(zones, rail, 'chord')
        print(f"   {r['label']} (h0 = {r['h0']} mm, {len(r['bodies'][0].nodes)} + {len(r['bodies'][1].nodes)} nodes, "
              f"{r['nk']} wavenumbers, rail cut {36 * r['size']:.0f} mm deep, wheel {40 * r['size']:.0f} mm above the crown):")
        print("     pair               | FE: C_ij, C_ii-C_ij, C_jj-C_ij | half-space, surface distance | 3-D distance, projected")
        for i, j in pairs:
            f = rel(C, i, j); s_ = rel(Hs, i, j); c_ = rel(Hc, i, j)
            fmt = lambda v: " ".join(f"{x * 1e9:8.2f}" for x in v)
            print(f"     {NAMES[i][:7]}-{NAMES[j][:7]:7s}    | {fmt(f)} | {fmt(s_)} | {fmt(c_)}")
        print("     self, FE minus half-space: " + ", ".join(f"{NAMES[i]} {(C[i, i] - Hs[i, i]) * 1e9:+.2f}" for i in range(3))
              + f"; C_root,tread from the rail {r['per']['rail'][0, 1] * 1e9:.2f}, the wheel {r['per']['wheel'][0, 1] * 1e9:.2f}")
    print("   (the FE's bodies are fixed ~40 mm away: their displacements lack the half-space's far tail, a near")
    print("   constant on every C_ij, which drops out of the split)\n")
    print("   The root's unit load: closing of the gap along the surface toward the tread, relative to the root")
    print("   patch's edge (the tread's normal displacement minus the root edge's; no coupling: the tread does not move)")
    for r in results:
        if r['label'] in ('mesh 3', 'mesh 2, root at track y 721 mm'):
            print(f"   {r['label']}:")
            profile_table(r)
    print()
    print(f"4. Load split at the same total {P_WRC.sum() / 1e3:.2f} kN (kN: root, tread, crown)")
    print(f"   reported: wrc {P_WRC / 1e3}, CONTACT {P_CONTACT / 1e3}, wrc merge_angle = 1.2 {P_WRC_MERGED / 1e3}")
    for r in results:
        out, _, _ = splits(r['zones'], r['C'], r['rail'])
        print(f"   {r['label']}:")
        for k, P in out.items():
            print(f"     {k:45s} {P[0] / 1e3:7.2f} {P[1] / 1e3:7.2f} {P[2] / 1e3:7.2f}")
    print(f"\n({time.time() - t0:.0f} s)")


if __name__ == '__main__':
    main()
