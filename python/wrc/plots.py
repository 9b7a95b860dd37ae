"""Plots of wrc results with matplotlib: profiles with contact points, pressure and traction maps, creep curves,
rolling radius difference and equivalent conicity, Y/Q of a sweep.

Every function takes results as the wrc calls return them and returns a matplotlib Figure (``path=`` also saves
it, the format from the extension). The figures are made on the Agg canvas without pyplot, so they need no display
and hold no memory once dropped; in Jupyter a figure is shown as the cell's value. The functions of one panel
(pressure_map, creep_curves, sweep_yq) also draw into given axes (ax=), e.g. of a pyplot figure.

Units on the axes are those a railway engineer reads: mm, kN, MPa, mrad or degrees; signs and frames follow
docs/design.md, section 2 (track frame: x along the track, z up, +y toward the LEFT rail; forces are those the
rail exerts on the wheel). Cross-sections are drawn as seen by someone looking in the direction of travel (+x):
the left rail on the left, so +y points to the left on the page.
"""

from __future__ import annotations

import io
import math
import os
from collections.abc import Mapping, Sequence

import numpy as np
from matplotlib.figure import Figure
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.collections import LineCollection
from matplotlib.colors import ListedColormap, BoundaryNorm
from matplotlib.patches import Patch as _LegendPatch

__all__ = ["profile_pair", "pressure_map", "traction_map", "creep_curves", "conicity", "sweep_yq"]

_MISSING = object()
_SIDES = ("left", "right")
# One colour per side in every figure (left: blue, right: red), and for the adhesion map.
_SIDE_COLOUR = {"left": "#1f5fa8", "right": "#c0392b"}
_ADHESION_COLOURS = ("#ffffff", "#3a6fc4", "#d9452b")   # outside, adhesion, slip


# ---------------------------------------------------------------------------------------------------------------
# Reading results: attributes (wrc.Result), mapping keys (dicts) or DataFrame columns, with errors that say what.

def _get(obj, name, default=_MISSING, what=None):
    """obj.name, obj[name] for a mapping, or default; an error naming the field and the object when absent."""
    if obj is not None:
        if isinstance(obj, Mapping):
            if name in obj:
                return obj[name]
        else:
            try:
                return getattr(obj, name)
            except AttributeError:
                pass
    if default is not _MISSING:
        return default
    raise ValueError(f"{what or type(obj).__name__} has no field '{name}'")


def _has(obj, name):
    return _get(obj, name, None) is not None


def _number(obj, name, what):
    v = _get(obj, name, what=what)
    try:
        f = float(v)
    except (TypeError, ValueError):
        raise TypeError(f"{what}.{name} is {type(v).__name__}, expected a number") from None
    return f


def _array(v, what):
    """A 1-D float array from a sequence or array; TypeError otherwise."""
    if isinstance(v, (str, bytes)) or not isinstance(v, (Sequence, np.ndarray)) and not hasattr(v, "__array__"):
        raise TypeError(f"{what} is {type(v).__name__}, expected a sequence of numbers")
    try:
        a = np.asarray(v, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(f"{what} holds something that is not a number") from None
    if a.ndim != 1:
        raise ValueError(f"{what} has shape {a.shape}, expected one dimension")
    return a


def _is_frame(obj):
    """A pandas DataFrame (duck-typed: pandas is imported only by the caller)."""
    return hasattr(obj, "columns") and hasattr(obj, "iloc")


def _frame_column(df, names, what):
    """A column of a DataFrame in SI units: names are (column, factor to SI) pairs, the first present is taken
    (wrc's tables name the unit in brackets, "y [m]"; the Lua studies' CSVs in the name, "y_mm")."""
    for n, factor in names:
        if n in df.columns:
            return np.asarray(df[n], dtype=float) * factor
    raise ValueError(f"{what} has none of the columns {', '.join(repr(n) for n, _ in names)} "
                     f"(its columns: {', '.join(map(str, df.columns))})")


def _frame_has(df, names):
    return any(n in df.columns for n, _ in names)


_Y_COLUMNS = (("y [m]", 1.0), ("y_mm", 1e-3), ("y [mm]", 1e-3))


# ---------------------------------------------------------------------------------------------------------------
# Figures.

class _Figure(Figure):
    """A matplotlib Figure that Jupyter shows as the value of a cell (a PNG), with or without pyplot."""

    def _repr_png_(self):
        buf = io.BytesIO()
        self.savefig(buf, format="png", dpi=self.dpi)
        return buf.getvalue()


def _figure(**kw):
    """A Figure on the Agg canvas: no display needed, and no pyplot state (a loop of figures holds no memory)."""
    fig = _Figure(**kw)
    FigureCanvasAgg(fig)
    return fig


def _finish(fig, path):
    if path is not None:
        path = os.fspath(path)
        folder = os.path.dirname(path)
        if folder and not os.path.isdir(folder):
            raise FileNotFoundError(f"path={path!r}: the folder {folder!r} does not exist")
        # Written to a temporary name first and then renamed, so that no half-written picture is left behind.
        root, ext = os.path.splitext(path)
        tmp = f"{root}.tmp{os.getpid()}{ext}"
        try:
            fig.savefig(tmp, dpi=fig.dpi)
            os.replace(tmp, path)
        finally:
            if os.path.exists(tmp):
                os.remove(tmp)
    return fig


def _check_path(path):
    if path is not None and not isinstance(path, (str, os.PathLike)):
        raise TypeError(f"path is {type(path).__name__}, expected a file name (str or os.PathLike)")


# ---------------------------------------------------------------------------------------------------------------
# Profile pair.

def _pose_of(result, pose):
    """The pose (y, z, roll, yaw) to draw: pose= first, then the result's (its pose table or its own fields)."""
    out = {"y": 0.0, "z": 0.0, "roll": 0.0, "yaw": 0.0}
    if result is not None:
        src = _get(result, "pose", None) or result
        for k in out:
            v = _get(src, k, None)
            if v is not None and not isinstance(v, str):
                out[k] = float(v)
    if pose is not None:
        if not isinstance(pose, Mapping):
            raise TypeError(f"pose is {type(pose).__name__}, expected a dict with y, z, roll, yaw (m, rad)")
        for k, v in pose.items():
            if k not in out:
                raise ValueError(f"pose: unknown key '{k}' (expected y, z, roll, yaw)")
            if not isinstance(v, (int, float)) or not math.isfinite(v):
                raise ValueError(f"pose['{k}'] = {v!r}, expected a finite number (m or rad)")
            out[k] = float(v)
    return out


def _placed(profile, what):
    y = _array(_get(profile, "y", what=what), what + ".y")
    z = _array(_get(profile, "z", what=what), what + ".z")
    if y.shape != z.shape or y.size < 2:
        raise ValueError(f"{what}: y and z must be of equal length >= 2 (got {y.size} and {z.size})")
    return y, z


def _contact_marks(result, side):
    """(point (y, z) m, normal (ny, nz), label) of the contacts of one wheel in a result."""
    w = _get(result, side, None) if result is not None else None
    if w is None:
        # A wheel result (ws.wheel) holds its patches at the top, with their side in each patch.
        patches = _get(result, "patches", None) if result is not None else None
        if patches is None:
            return []
        patches = [p for p in patches if _get(p, "side", side) == side]
        w = {"patches": patches}
    marks = []
    patches = _get(w, "patches", None)
    if patches is not None:           # elastic: the areas' centres of pressure
        for p in patches:
            pt, n = _get(p, "point", None), _get(p, "normal", None)
            if pt is None or n is None:
                continue
            label = "N = %.1f kN, %.1f°" % (_number(p, "normal_force", "patch") / 1e3,
                                           math.degrees(_number(p, "angle", "patch")))
            marks.append(((float(pt.y if hasattr(pt, "y") else pt["y"]), float(_get(pt, "z"))),
                          (float(_get(n, "y")), float(_get(n, "z"))), label))
        return marks
    contacts = _get(w, "contacts", None)
    if contacts is not None:          # rigid: the touching point first, then second points
        for k, c in enumerate(contacts):
            pt, n = _get(c, "point"), _get(c, "normal")
            label = "%.1f°" % math.degrees(float(_get(c, "angle")))
            if k == 0 and _get(w, "normal_force", None) is not None:
                label = "N = %.1f kN, " % (float(_get(w, "normal_force")) / 1e3) + label
            elif k > 0:
                label = "gap %.3f mm, " % (float(_get(c, "gap")) * 1e3) + label
            marks.append(((float(_get(pt, "y")), float(_get(pt, "z"))), (float(_get(n, "y")), float(_get(n, "z"))),
                          label))
    return marks


def profile_pair(ws, result=None, *, pose=None, sides=_SIDES, normals=True, path=None, figsize=None):
    """The wheel and rail profiles of a wheelset in the track frame at a pose, the contact points marked.

    ws: the wheelset (its placed profiles ws.left_wheel, ws.left_rail, ... are drawn). result: a result of
    ws.contact, ws.equilibrium, ws.rigid, ws.wheel or a sweep's case: its pose is drawn (pose= overrides any of
    y, z, roll, yaw, in m and rad) and its contacts marked -- elastic results at each area's centre of pressure
    with its normal force and contact angle, rigid ones at each contact point. normals: draw each contact's normal
    (from the rail into the wheel). One panel per wheel, cross-section x = 0 seen in the direction of travel: the
    left wheel on the left, +y to the left on the page (a yaw is not drawn; the contact points are where the
    result puts them). Returns the Figure.
    """
    _check_path(path)
    if isinstance(sides, str):
        sides = (sides,)
    for s in sides:
        if s not in _SIDES:
            raise ValueError(f"sides: '{s}' is not a side (left or right)")
    p = _pose_of(result, pose)
    c, s = math.cos(p["roll"]), math.sin(p["roll"])
    fig = _figure(figsize=figsize or (5.6 * len(sides) + 0.4, 3.5), layout="constrained")
    axes = fig.subplots(1, len(sides), squeeze=False)[0]
    for ax, side in zip(axes, sides):
        wy, wz = _placed(_get(ws, side + "_wheel", what="wheelset"), f"ws.{side}_wheel")
        ry, rz = _placed(_get(ws, side + "_rail", what="wheelset"), f"ws.{side}_rail")
        # Wheelset frame -> track frame at x = 0: p = (0, y, z) + Rx(roll) p_w (docs/design.md, section 2).
        ty, tz = p["y"] + c * wy - s * wz, p["z"] + s * wy + c * wz
        top = rz.max()
        ybox = (ry.min() - 0.040, ry.max() + 0.012) if side == "left" else (ry.min() - 0.012, ry.max() + 0.040)
        ztop, zbot = top + 0.028, rz.min()
        # Rail: its head, filled down to its lowest point; wheel: filled up to the top of the panel.
        ax.fill(np.r_[ry, ry[-1], ry[0]] * 1e3, np.r_[rz, zbot, zbot] * 1e3, color="#b9b9b9", lw=0, zorder=1)
        ax.plot(ry * 1e3, rz * 1e3, color="#444444", lw=1.2, zorder=2, label="rail")
        inside = (ty > ybox[0] - 0.02) & (ty < ybox[1] + 0.02)
        if inside.sum() >= 2:
            yy, zz = ty[inside], tz[inside]
            ax.fill(np.r_[yy, yy[-1], yy[0]] * 1e3, np.r_[zz, ztop + 0.01, ztop + 0.01] * 1e3,
                    color=_SIDE_COLOUR[side], alpha=0.15, lw=0, zorder=1)
            ax.plot(yy * 1e3, zz * 1e3, color=_SIDE_COLOUR[side], lw=1.2, zorder=2, label="wheel")
        for k, ((py, pz), (ny, nz), label) in enumerate(_contact_marks(result, side)):
            ax.plot(py * 1e3, pz * 1e3, "o", color="k", ms=5, zorder=4)
            if normals:
                L = 12.0   # mm: the normal drawn from the rail into the wheel
                ax.annotate("", xy=(py * 1e3 + L * ny, pz * 1e3 + L * nz), xytext=(py * 1e3, pz * 1e3),
                            arrowprops=dict(arrowstyle="->", color="k", lw=1), zorder=4)
            # The label above the point, one line per contact, clear of the profiles.
            ax.annotate(label, xy=(py * 1e3, pz * 1e3), xytext=(py * 1e3, (ztop - 0.003 - 0.0055 * k) * 1e3),
                        fontsize=8, ha="center", va="top", arrowprops=dict(arrowstyle="-", color="0.5", lw=0.6),
                        bbox=dict(boxstyle="round,pad=0.2", fc="white", ec="0.7", lw=0.5), zorder=5)
        wheel_result = _get(result, side, None) if result is not None else None
        if wheel_result is not None and _get(wheel_result, "lifted", False) is True:
            ax.text(0.5, 0.93, "lifted: no contact", transform=ax.transAxes, ha="center", va="top", fontsize=9,
                    color=_SIDE_COLOUR[side])
        ax.set_xlim(ybox[1] * 1e3, ybox[0] * 1e3)       # +y to the left: seen in the direction of travel
        ax.set_ylim(zbot * 1e3, ztop * 1e3)
        ax.set_aspect("equal")
        ax.set_title(f"{side} wheel and rail", color=_SIDE_COLOUR[side])
        ax.set_xlabel("y (mm), track frame, + toward the left rail")
        ax.set_ylabel("z (mm)")
        ax.grid(True, lw=0.3, alpha=0.6)
    fig.suptitle("y = %.2f mm, z = %.3f mm, roll = %.3f mrad, yaw = %.2f mrad; looking in the direction of travel"
                 % (p["y"] * 1e3, p["z"] * 1e3, p["roll"] * 1e3, p["yaw"] * 1e3), fontsize=9)
    return _finish(fig, path)


# ---------------------------------------------------------------------------------------------------------------
# Maps of a contact area.

def _grid_of(patch, field, hint):
    g = _get(patch, "grid", what="patch")
    nx, ny = int(_get(g, "nx")), int(_get(g, "ny"))
    dx, dy, x0, y0 = (float(_get(g, k)) for k in ("dx", "dy", "x0", "y0"))
    v = _get(patch, field, None)
    if v is None:
        raise ValueError(f"the patch has no '{field}' grid: {hint}")
    a = np.asarray(v, dtype=float)
    if a.shape != (ny, nx):
        raise ValueError(f"patch.{field} has shape {a.shape}, expected (grid.ny, grid.nx) = ({ny}, {nx})")
    # Element edges (mm) for pcolormesh: centres at x0 + i dx.
    xe = (x0 + (np.arange(nx + 1) - 0.5) * dx) * 1e3
    ye = (y0 + (np.arange(ny + 1) - 0.5) * dy) * 1e3
    return a, xe, ye


def _outline(ax, inside, xe, ye, **style):
    """The edge of the contact: the element edges between an element in contact and one outside (or the grid's
    border), so that the line follows the elements the map shows."""
    pad = np.zeros((inside.shape[0] + 2, inside.shape[1] + 2), dtype=bool)
    pad[1:-1, 1:-1] = inside
    segs = []
    vj, vi = np.nonzero(pad[1:-1, 1:] != pad[1:-1, :-1])        # edges between columns i-1 and i (x = xe[i])
    segs += [((xe[i], ye[j]), (xe[i], ye[j + 1])) for j, i in zip(vj, vi)]
    hj, hi = np.nonzero(pad[1:, 1:-1] != pad[:-1, 1:-1])        # edges between rows j-1 and j (y = ye[j])
    segs += [((xe[i], ye[j]), (xe[i + 1], ye[j])) for j, i in zip(hj, hi)]
    if segs:
        ax.add_collection(LineCollection(segs, **{"colors": "k", "linewidths": 0.8, **style}))


def _map_labels(ax, patch):
    conformal = _get(patch, "surface", "planar") == "conformal" or _has(patch, "rows")
    ax.set_xlabel(("x along the track" if conformal else "x along t1") + " (mm), rolling direction →")
    ax.set_ylabel("s along the rail's profile (mm)" if conformal else "y along t2 (mm)")
    ax.set_aspect("equal")


def _colorbar(fig, mappable, ax, label):
    """A colour bar as tall as the map (an inset beside the axes: it follows their equal-aspect box)."""
    cax = ax.inset_axes([1.03, 0.0, 0.035, 1.0])
    fig.colorbar(mappable, cax=cax, label=label)


def _gauge_note(ax, patch, ye):
    """Mark which end of the lateral axis is toward the gauge side (the flange), where the contact angle rises."""
    rows = _get(patch, "rows", None)
    if rows is not None and _get(rows, "angle", None) is not None:
        ang = np.asarray(_get(rows, "angle"), dtype=float)
        up = ang.size > 1 and ang[-1] > ang[0]
    else:
        # Planar: t2 = n x t1 points toward +y on both wheels; the gauge side is -y on the left wheel.
        up = _get(patch, "side", "left") == "right"
    ax.annotate("gauge side ↑" if up else "gauge side ↓", xy=(1.0, 1.0 if up else 0.0), xycoords="axes fraction",
                xytext=(-4, -4 if up else 4), textcoords="offset points", ha="right", va="top" if up else "bottom",
                fontsize=8, color="0.3")


def _patch_title(patch):
    side = _get(patch, "side", "")
    return "%s wheel: N = %.1f kN, pmax = %.0f MPa, area %.0f mm², angle %.1f°" % (
        side, _number(patch, "normal_force", "patch") / 1e3, _number(patch, "pmax", "patch") / 1e6,
        _number(patch, "area", "patch") * 1e6, math.degrees(_number(patch, "angle", "patch")))


def _tidy(v):
    """Round-off (|v| < 1e-12) shown as 0 in titles."""
    return 0.0 if abs(v) < 1e-12 else v


def pressure_map(patch, *, ax=None, path=None, figsize=None, cmap="viridis"):
    """The normal pressure (MPa) of one contact area on its grid, the contact's edge outlined.

    patch: an area of a result (e.g. e.left.patches[0]) solved with grids (the default of ws.contact and
    ws.equilibrium). x runs along the track (the rolling direction), the lateral axis along t2 on a planar area or
    along the rail's profile (s) on a conformal one; which end is the gauge side is marked. Elements out of contact
    are blank. ax: draw into these axes (the figure is theirs). Returns the Figure.
    """
    _check_path(path)
    p, xe, ye = _grid_of(patch, "pressure", "solve with grids=True (the default)")
    # The height follows the grid's shape (equal scales on both axes), within reason.
    ratio = (ye[-1] - ye[0]) / (xe[-1] - xe[0])
    fig = ax.figure if ax is not None else _figure(figsize=figsize or (6.4, min(8.0, max(2.8, 5.0 * ratio + 1.2))),
                                                   layout="constrained")
    ax = ax or fig.subplots()
    mpa = np.where(p > 0, p / 1e6, np.nan)
    m = ax.pcolormesh(xe, ye, mpa, cmap=cmap, vmin=0, shading="flat")
    _outline(ax, p > 0, xe, ye)
    _colorbar(fig, m, ax, "normal pressure p (MPa)")
    _map_labels(ax, patch)
    _gauge_note(ax, patch, ye)
    ax.set_title(_patch_title(patch), fontsize=9)
    return _finish(fig, path)


def traction_map(patch, *, path=None, figsize=None, arrows=14):
    """A rolling contact area: adhesion and slip zones with the tangential tractions, |traction| (MPa) and the
    slip velocity (mm/s) with its direction.

    patch: an area of a result solved with rolling keys (V= or creepage=, mu=) and grids. The wheel rolls toward +x:
    the leading edge is on the right of each panel. Traction arrows are the traction on the wheel (px, py); slip
    arrows the wheel's slip relative to the rail. arrows: about this many arrows along the longer side. Returns the
    Figure.
    """
    _check_path(path)
    hint = "solve with rolling keys (V= or creepage=, and mu=) and grids=True"
    state, xe, ye = _grid_of(patch, "adhesion_map", hint)
    px, _, _ = _grid_of(patch, "px", hint)
    py, _, _ = _grid_of(patch, "py", hint)
    sx, _, _ = _grid_of(patch, "slip_x", hint)
    sy, _, _ = _grid_of(patch, "slip_y", hint)
    if not isinstance(arrows, int) or arrows < 2:
        raise ValueError(f"arrows = {arrows!r}, expected an integer >= 2")
    xc, yc = 0.5 * (xe[1:] + xe[:-1]), 0.5 * (ye[1:] + ye[:-1])
    X, Y = np.meshgrid(xc, yc)
    inside = state > 0
    step = max(1, int(round(max(state.shape) / arrows)))
    sub = (slice(step // 2, None, step), slice(step // 2, None, step))
    fig = _figure(figsize=figsize or (15.0, 4.6), layout="constrained")
    ax1, ax2, ax3 = fig.subplots(1, 3, sharex=True, sharey=True)

    cmap = ListedColormap(_ADHESION_COLOURS)
    ax1.pcolormesh(xe, ye, state, cmap=cmap, norm=BoundaryNorm([-0.5, 0.5, 1.5, 2.5], 3), shading="flat")
    show = inside[sub]
    ax1.quiver(X[sub][show], Y[sub][show], px[sub][show], py[sub][show], color="k", width=0.004)
    ax1.legend(handles=[_LegendPatch(color=_ADHESION_COLOURS[1], label="adhesion"),
                        _LegendPatch(color=_ADHESION_COLOURS[2], label="slip")], loc="upper left", fontsize=8)
    ax1.set_title("adhesion and slip; arrows: traction on the wheel", fontsize=9)

    t = np.where(inside, np.hypot(px, py) / 1e6, np.nan)
    m2 = ax2.pcolormesh(xe, ye, t, cmap="magma_r", vmin=0, shading="flat")
    _colorbar(fig, m2, ax2, "|tangential traction| (MPa)")
    ax2.set_title("tangential traction", fontsize=9)

    sl = np.where(inside, np.hypot(sx, sy) * 1e3, np.nan)
    m3 = ax3.pcolormesh(xe, ye, sl, cmap="cividis", vmin=0, shading="flat")
    _colorbar(fig, m3, ax3, "|slip velocity| (mm/s)")
    moving = inside[sub] & (np.hypot(sx, sy)[sub] > 0)
    if moving.any():
        ax3.quiver(X[sub][moving], Y[sub][moving], sx[sub][moving], sy[sub][moving], color="w", width=0.004)
    ax3.set_title("slip of the wheel relative to the rail", fontsize=9)
    for ax in (ax1, ax2, ax3):
        _outline(ax, inside, xe, ye, linewidths=0.6)
        _map_labels(ax, patch)
        _gauge_note(ax, patch, ye)
    cr = _get(patch, "creepage", None)
    creep = ""
    if cr is not None:
        xi, eta, phi = (_tidy(float(_get(cr, k))) for k in ("xi", "eta", "phi"))
        creep = "; ξ = %.3g, η = %.3g, φ = %.3g 1/m" % (xi, eta, phi)
    mu = _get(patch, "mu", None)
    V = _get(patch, "V", None)
    if V is not None:
        creep += "; V = %.3g m/s" % float(V)
    fig.suptitle("%s; μ = %.2f, Fx = %.2f kN, Fy = %.2f kN, adhesion %.0f %%%s" % (
        _patch_title(patch), float(_get(mu, "kinetic")) if mu is not None else float("nan"),
        _number(patch, "Fx", "patch") / 1e3, _number(patch, "Fy", "patch") / 1e3,
        100 * _number(patch, "adhesion", "patch"), creep), fontsize=9)
    return _finish(fig, path)


# ---------------------------------------------------------------------------------------------------------------
# Creep curves.

_CREEP_AXIS = {"Fx": ("xi", "longitudinal creepage ξ (‰)", 1e3), "Fy": ("eta", "lateral creepage η (‰)", 1e3)}


def creep_curves(curves, *, force="Fx", creepage=None, normalise=True, linear=None, ax=None, path=None,
                 figsize=None, title=None):
    """Creep force against creepage, one line per entry of curves (e.g. per method or per mu).

    curves: a dict label -> list of contact areas (patches) solved at increasing creepage, e.g.
    {"exact": [c.left.patches[0] for c in ...], "FASTSIM": [...]}. force: "Fx" (along t1) or "Fy" (along t2); the
    creepage on the x axis is the area's own (patch.creepage: xi for Fx, eta for Fy; creepage= "xi", "eta" or
    "phi" to choose). normalise: plot -F / (mu N) (each area's mu.kinetic and normal force), else -F in kN; the
    minus sign makes a braking curve (xi > 0, Fx < 0) positive. linear: a slope dF/dcreepage (N per unit
    creepage, e.g. Kalker's G c^2 C11) or a dict label -> slope: drawn dashed from the origin, up to the saturation.
    Returns the Figure.
    """
    _check_path(path)
    if not isinstance(curves, Mapping) or not curves:
        raise TypeError(f"curves is {type(curves).__name__}, expected a non-empty dict label -> list of patches")
    if force not in _CREEP_AXIS:
        raise ValueError(f"force = {force!r}: expected 'Fx' or 'Fy'")
    key, xlabel, xscale = _CREEP_AXIS[force]
    if creepage is not None:
        if creepage not in ("xi", "eta", "phi"):
            raise ValueError(f"creepage = {creepage!r}: expected 'xi', 'eta' or 'phi'")
        key = creepage
        xlabel, xscale = ("spin creepage φ (1/m)", 1.0) if key == "phi" else (
            _CREEP_AXIS["Fx" if key == "xi" else "Fy"][1], 1e3)
    fig = ax.figure if ax is not None else _figure(figsize=figsize or (6.4, 4.6), layout="constrained")
    ax = ax or fig.subplots()
    muN_ref = None
    xmax = 0.0
    for label, patches in curves.items():
        if isinstance(patches, (str, bytes)) or not isinstance(patches, Sequence) or len(patches) == 0:
            raise TypeError(f"curves[{label!r}] is {type(patches).__name__}, expected a non-empty list of patches")
        x, f = np.empty(len(patches)), np.empty(len(patches))
        for i, p in enumerate(patches):
            what = f"curves[{label!r}][{i}]"
            cr = _get(p, "creepage", None)
            if cr is None:
                raise ValueError(f"{what} has no creepage: solve the contact with rolling keys (V= or creepage=)")
            x[i] = _number(cr, key, what + ".creepage")
            F = _number(p, force, what)
            muN = float(_get(_get(p, "mu", what=what), "kinetic")) * _number(p, "normal_force", what)
            muN_ref = muN_ref or muN
            f[i] = -F / muN if normalise else -F / 1e3
        order = np.argsort(x)
        ax.plot(x[order] * xscale, f[order], marker="o", ms=3, lw=1.5, label=str(label))
        xmax = max(xmax, float(np.max(np.abs(x))))
    if linear is not None:
        slopes = linear if isinstance(linear, Mapping) else {"linear theory": linear}
        for label, slope in slopes.items():
            if not isinstance(slope, (int, float)) or not math.isfinite(slope) or slope <= 0:
                raise ValueError(f"linear[{label!r}] = {slope!r}: expected a positive slope (N per unit creepage)")
            # The line up to where it reaches the saturation |F| = mu N (or the curves' end).
            xs = min(xmax, (muN_ref or 0) / slope) if muN_ref else xmax
            xx = np.array([0.0, xs])
            yy = xx * slope / (muN_ref if normalise else 1e3)
            ax.plot(xx * xscale, yy, "--", color="0.3", lw=1.2, label=str(label))
    if normalise:
        ax.axhline(1.0, color="0.6", lw=0.8, ls=":")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(f"−{force} / (μ N)" if normalise else f"−{force} (kN)")
    ax.set_xlim(left=0)
    ax.set_ylim(bottom=0)
    ax.grid(True, lw=0.3, alpha=0.6)
    ax.legend(fontsize=8, loc="lower right")
    if title:
        ax.set_title(title, fontsize=10)
    return _finish(fig, path)


# ---------------------------------------------------------------------------------------------------------------
# Rolling radius difference and equivalent conicity.

def _unwrap_conicity(r):
    """ws.conicity may return (tan_gammas, details): the details are what is drawn."""
    if isinstance(r, tuple):
        for item in reversed(r):
            if _has(item, "yhat") or _has(item, "dr"):
                return item
        raise ValueError("a tuple of results without a conicity result (yhat, tan_gamma) in it")
    return r


def _dr_of(r, what):
    """(y m, dr m, flange bool or None) of a conicity result's dr table, a geometry table or a Δr table."""
    if _is_frame(r):
        y = _frame_column(r, _Y_COLUMNS, what)
        dr = _frame_column(r, (("rolling_radius_difference [m]", 1.0), ("rolling_radius_difference_mm", 1e-3),
                               ("dr [m]", 1.0), ("dr_mm", 1e-3)), what)
        return y, dr, None
    d = _get(r, "dr", None)
    if d is not None and not isinstance(d, (np.ndarray, Sequence)):     # conicity result: its table
        r = d
    rows = _get(r, "rows", None)
    if rows is not None and not _has(r, "dr"):                           # geometry table: its rows
        y = np.array([float(_get(row, "y")) for row in rows])
        dr = np.array([float(_get(row, "rolling_radius_difference", float("nan"))) for row in rows])
        return y, dr, None
    if _has(r, "dr") and _has(r, "y"):
        y, dr = _array(_get(r, "y"), what + ".y"), _array(_get(r, "dr"), what + ".dr")
        if y.shape != dr.shape:
            raise ValueError(f"{what}: y and dr differ in length ({y.size} and {dr.size})")
        fl = _get(r, "flange", None)
        return y, dr, (np.asarray(fl, dtype=bool) if fl is not None else None)
    return None


def conicity(results, *, labels=None, path=None, figsize=None, title=None):
    """Rolling radius difference against y and EN 15302 equivalent conicity tan(gamma_e) against the amplitude.

    results: one result or a list: ws.conicity's result (both panels: its Δr table and tan(gamma_e)),
    wrc.conicity's (tan(gamma_e) only), or a geometry table (ws.geometry_table's result or its DataFrame: Δr
    only). labels: one per result (default "1", "2", ...). Δr = r_left - r_right (mm), y + toward the left rail;
    points of the table with flange contact are marked, and the Δr axis spans 1.6 times the largest Δr without
    flange contact (flange contact runs off the panel). Returns the Figure.
    """
    _check_path(path)
    items = list(results) if isinstance(results, list) else [results]
    if not items:
        raise ValueError("results is empty: give at least one conicity or geometry table result")
    if labels is None:
        labels = [str(k + 1) for k in range(len(items))] if len(items) > 1 else [""]
    if isinstance(labels, str) or len(labels) != len(items):
        raise ValueError(f"labels: expected a list of {len(items)} label(s), got {labels!r}")
    fig = _figure(figsize=figsize or (11.5, 4.4), layout="constrained")
    ax1, ax2 = fig.subplots(1, 2)
    n_dr = n_tan = 0
    tread = 0.0     # the largest |Δr| without flange contact (m): the panel's scale
    for k, (r, label) in enumerate(zip(items, labels)):
        what = f"results[{k}]" if len(items) > 1 else "results"
        r = _unwrap_conicity(r)
        colour = f"C{k}"
        dr = _dr_of(r, what)
        if dr is not None:
            y, d, flange = dr
            ax1.plot(y * 1e3, d * 1e3, color=colour, lw=1.5, label=label or None)
            if flange is not None and flange.any():
                ax1.plot(y[flange] * 1e3, d[flange] * 1e3, "x", color=colour, ms=4,
                         label=(label + ": " if label else "") + "flange contact")
            ok = np.isfinite(d) & (~flange if flange is not None else True)
            tread = max(tread, float(np.max(np.abs(d[ok]))) if ok.any() else 0.0)
            n_dr += 1
        if _has(r, "yhat") and _has(r, "tan_gamma"):
            a = _array(_get(r, "yhat"), what + ".yhat")
            t = _array(_get(r, "tan_gamma"), what + ".tan_gamma")
            if a.shape != t.shape:
                raise ValueError(f"{what}: yhat and tan_gamma differ in length ({a.size} and {t.size})")
            method = _get(r, "method", "")
            ax2.plot(a * 1e3, t, marker="o", ms=3, lw=1.5, color=colour,
                     label=(label + (f" ({method})" if method else "")) or None)
            n_tan += 1
        if dr is None and not (_has(r, "yhat") and _has(r, "tan_gamma")):
            raise ValueError(f"{what} is neither a conicity result (yhat, tan_gamma) nor a Δr or geometry table")
    ax1.axhline(0, color="0.6", lw=0.6)
    ax1.axvline(0, color="0.6", lw=0.6)
    if tread > 0:
        # The tread's Δr readable: flange contact (10 mm and more) runs off the panel beyond 1.6 x the tread's.
        lo, hi = ax1.get_ylim()
        ax1.set_ylim(max(lo, -1.6e3 * tread), min(hi, 1.6e3 * tread))
    ax1.set_xlabel("lateral displacement y (mm), + toward the left rail")
    ax1.set_ylabel("Δr = r_left − r_right (mm)")
    ax1.set_title("rolling radius difference" if n_dr else "rolling radius difference: no table given", fontsize=10)
    ax2.set_xlabel("amplitude ŷ (mm)")
    ax2.set_ylabel("equivalent conicity tan γe (−)")
    ax2.set_title("EN 15302 equivalent conicity" if n_tan else "equivalent conicity: none given", fontsize=10)
    ax2.set_xlim(left=0)
    ax2.set_ylim(bottom=0)
    for ax in (ax1, ax2):
        ax.grid(True, lw=0.3, alpha=0.6)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=8)
    if title:
        fig.suptitle(title, fontsize=10)
    return _finish(fig, path)


# ---------------------------------------------------------------------------------------------------------------
# Y/Q of a sweep.

def _sweep_series(sweep, what):
    """{yaw (rad): (y m, Y/Q, rigid Y/Q or None, past flange climb, rigid past flange climb)} of a sweep's
    DataFrame or its list of cases."""
    if _is_frame(sweep):
        y = _frame_column(sweep, _Y_COLUMNS, what)
        yq = _frame_column(sweep, (("Y_Q", 1.0), ("Y/Q", 1.0)), what)
        n = len(y)
        yaw_names = (("yaw [rad]", 1.0), ("yaw_deg", math.pi / 180), ("yaw [deg]", math.pi / 180))
        yaw = _frame_column(sweep, yaw_names, what) if _frame_has(sweep, yaw_names) else np.zeros(n)
        conv = (_frame_column(sweep, (("converged", 1),), what) != 0 if "converged" in sweep.columns
                else np.ones(n, bool))
        climb = (_frame_column(sweep, (("flange_climb", 1),), what) != 0 if "flange_climb" in sweep.columns
                 else np.zeros(n, bool))
        rigid_names = (("rigid.Y_Q", 1.0), ("rigid_Y_Q", 1.0))
        rq = _frame_column(sweep, rigid_names, what) if _frame_has(sweep, rigid_names) else None
        rclimb = (_frame_column(sweep, (("rigid.flange_climb", 1),), what) != 0
                  if "rigid.flange_climb" in sweep.columns else np.zeros(n, bool))
        cases = list(zip(y, yq, yaw, conv, rq if rq is not None else np.full(n, np.nan), climb, rclimb))
        has_rigid = rq is not None
    else:
        rows = _get(sweep, "cases", None) or _get(sweep, "rows", None) or sweep
        if isinstance(rows, (str, bytes)) or not isinstance(rows, Sequence):
            raise TypeError(f"{what} is {type(sweep).__name__}, expected a sweep's result (a list of cases) or its "
                            "DataFrame (columns y_mm, Y_Q, yaw_deg)")
        cases, has_rigid = [], False
        for i, c in enumerate(rows):
            w = f"{what}[{i}]"
            rg = _get(c, "rigid", None)
            rq = float(_get(rg, "Y_Q", float("nan"))) if rg is not None else float("nan")
            has_rigid |= rg is not None
            cases.append((_number(c, "y", w), float(_get(c, "Y_Q", float("nan"))), float(_get(c, "yaw", 0.0)),
                          bool(_get(c, "converged", True)), rq, bool(_get(c, "flange_climb", False)),
                          bool(_get(rg, "flange_climb", False)) if rg is not None else False))
    if not cases:
        raise ValueError(f"{what} has no cases")
    series = {}
    for y, yq, yaw, ok, rq, climb, rclimb in cases:
        series.setdefault(round(float(yaw), 12), []).append((y, yq if ok else np.nan, rq, float(climb), float(rclimb)))
    out = {}
    for yaw, pts in sorted(series.items()):
        pts.sort()
        a = np.array(pts, dtype=float)
        out[yaw] = (a[:, 0], a[:, 1], a[:, 2] if has_rigid else None, a[:, 3] > 0, a[:, 4] > 0)
    return out


def sweep_yq(sweep, *, limit=None, rigid=True, ax=None, path=None, figsize=None, title=None):
    """Y/Q against the lateral displacement y, one line per yaw of a sweep, the rigid reference dashed.

    sweep: ws.sweep's result (its cases; with rigid=True in the call each case's rigid reference is drawn too,
    unless rigid=False here) or its DataFrame (columns y_mm, Y_Q, yaw_deg, converged; rigid_Y_Q if present).
    Y is the lateral force a support at the wheelset centre applies (> 0 toward the left rail), Q the vertical
    load. Cases that did not converge are gaps; cases past flange climb (beyond the flange's steepest part,
    Nadal's limit, or a wheel lifted) are crossed. limit: a derailment limit (e.g. Nadal's) drawn at +-limit.
    Returns the Figure.
    """
    _check_path(path)
    if limit is not None and (not isinstance(limit, (int, float)) or not math.isfinite(limit) or limit <= 0):
        raise ValueError(f"limit = {limit!r}: expected a positive Y/Q")
    series = _sweep_series(sweep, "sweep")
    fig = ax.figure if ax is not None else _figure(figsize=figsize or (6.8, 4.6), layout="constrained")
    ax = ax or fig.subplots()
    climbed = False
    for k, (yaw, (y, yq, rq, climb, rclimb)) in enumerate(series.items()):
        name = "yaw %.3g°" % math.degrees(yaw)
        ax.plot(y * 1e3, yq, color=f"C{k}", lw=1.6, marker="." if y.size <= 60 else None, label=name + ", elastic")
        marks = [(climb, yq)]
        if rigid and rq is not None and np.isfinite(rq).any():
            ax.plot(y * 1e3, rq, color=f"C{k}", lw=1.0, ls="--", label=name + ", rigid")
            marks.append((rclimb, rq))
        for past, v in marks:
            if past.any():
                ax.plot(y[past] * 1e3, v[past], "x", color="k", ms=6, label=None if climbed else "past flange climb")
                climbed = True
    if limit is not None:
        for s in (1, -1):
            ax.axhline(s * limit, color="k", lw=0.9, ls=":")
        ax.text(0.01, limit, " limit %.2f" % limit, transform=ax.get_yaxis_transform(), va="bottom", fontsize=8)
    ax.axhline(0, color="0.6", lw=0.6)
    ax.axvline(0, color="0.6", lw=0.6)
    ax.set_xlabel("lateral displacement y (mm), + toward the left rail")
    ax.set_ylabel("Y/Q (−)")
    ax.grid(True, lw=0.3, alpha=0.6)
    ax.legend(fontsize=8, loc="upper left")
    if title:
        ax.set_title(title, fontsize=10)
    return _finish(fig, path)
