// The conformal surface (surface.hpp): a contact area on the rail's surface unrolled (wrc/wheelset/conformal.hpp says
// what and why; docs/design.md section 3).
#include "surface.hpp"

#include "wrc/core/error.hpp"
#include "wrc/geometry/wheel_surface.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <memory>

namespace wrc {

const char* surface_name(ContactSurface surface) {
  return surface == ContactSurface::conformal ? "conformal" : "planar";
}

namespace areas {
namespace {

// One rail line of the reference curve across an area: its arc length, its point, the wheel's normal at its
// deepest point and h(x) along it.
struct SurfaceLine {
  double S = 0;          // arc length along the rail profile from the side's first line (m)
  double y = 0, z = 0;   // the line (track frame, m)
  Eigen::Vector2d n;     // (n_y, n_z), unit: the bisector of the rail's normal and the wheel's (at the normal foot of
                         // the line's deepest point, along which its depth is measured; x component dropped): the
                         // normal of the surface midway between them
  Eigen::Vector2d dn = Eigen::Vector2d::Zero();  // dn / da: n's turning as the wheel moves down by a (1/m), from the
                                                 // foot's sliding along the wheel (wheel_foot_normal_rate)
  LineProfile h;         // depth along the wheel's normal as a function of track x (v, u0 unused)
  double deepening = 1;  // dh/dz before h_gain: the z part of the wheel's normal at the deepest point's lateral
                         // position (the radial depth's; times h_gain, 1 - 2 bend d, the normal foot's)
};

double chord(const RailLines& rail, int r) {  // between lines r and r + 1 (m)
  return std::hypot(rail.y[r + 1] - rail.y[r], rail.z[r + 1] - rail.z[r]);
}

// The area's origin in unrolled coordinates (track x, arc length S): the segments' mid-points weighted by their
// shares of the inter-penetration volume (the planar path's plane origin, on the surface), so that it moves
// continuously with the pose; equal weights when only tangencies are left.
Eigen::Vector2d surface_origin(const std::vector<SegmentInfo>& all, const std::vector<double>& S_of_segment) {
  double W = 0;
  Eigen::Vector2d o = Eigen::Vector2d::Zero();
  for (std::size_t k = 0; k < all.size(); ++k) {
    W += all[k].weight;
    o += all[k].weight * Eigen::Vector2d(all[k].xm, S_of_segment[k]);
  }
  if (W > 0) return o / W;
  o.setZero();
  for (std::size_t k = 0; k < all.size(); ++k) o += Eigen::Vector2d(all[k].xm, S_of_segment[k]);
  return o / static_cast<double>(all.size());
}

// The grid on the unrolled surface, covering the segments (x from their ends, s from their lines) plus the margin:
// element centres on the rail's own lattice, x and s - s_lattice at integer multiples of the element
// (ContactModel::rail_lattice_origin), in coordinates relative to the origin o. The rail does not move, so neither
// does the lattice: h at an element changes only with the wheel's pose (continuously), a warm start finds the
// previous pressures on the same points, and a deeper pose on the same lattice differs from the shallower one only by
// h (what the fixed-surface sensitivities and ws:wheel's predictions assume). Anchored at a moving origin instead,
// the elements would slide with the pose.
halfspace::Grid surface_grid(const ContactOptions& opt, const std::vector<SegmentInfo>& all,
                           const std::vector<double>& S_of_segment, const Eigen::Vector2d& o, double s_lattice,
                           int side, const Pose& pose) {
  double xmin = INFINITY, xmax = -INFINITY, smin = INFINITY, smax = -INFINITY;
  for (std::size_t k = 0; k < all.size(); ++k) {
    xmin = std::min(xmin, all[k].xm - 0.5 * all[k].L);
    xmax = std::max(xmax, all[k].xm + 0.5 * all[k].L);
    smin = std::min(smin, S_of_segment[k]);
    smax = std::max(smax, S_of_segment[k]);
  }
  const double e = opt.element;
  halfspace::Grid grid = span_grid(opt, index_span(xmin, xmax, e, opt.margin),
                                 index_span(smin - s_lattice, smax - s_lattice, e, opt.margin), all, side, pose);
  grid.x0 = grid.x0 - o.x();
  grid.y0 = grid.y0 + s_lattice - o.y();
  return grid;
}

Eigen::Vector2d lateral_normal(const Eigen::Vector3d& n) {
  const Eigen::Vector2d v(n.y(), n.z());
  return v.norm() > 0 ? Eigen::Vector2d(v.normalized()) : Eigen::Vector2d(0, 1);
}

// The rail's outward normal (n_y, n_z) at line r: perpendicular to the chord between its neighbours (one-sided at
// the ends); the lines are ordered by increasing y, so (-dz, dy) points out of the rail.
Eigen::Vector2d rail_normal(const RailLines& rail, int r) {
  const int a = std::max(0, r - 1), b = std::min(rail.count() - 1, r + 1);
  const Eigen::Vector2d n(-(rail.z[b] - rail.z[a]), rail.y[b] - rail.y[a]);
  return n.norm() > 0 ? Eigen::Vector2d(n.normalized()) : Eigen::Vector2d(0, 1);
}

// The normal of the surface midway between wheel and rail: the bisector of their normals.
Eigen::Vector2d mid_normal(const Eigen::Vector2d& wheel, const Eigen::Vector2d& rail) {
  const Eigen::Vector2d n = wheel + rail;
  return n.norm() > 0 ? Eigen::Vector2d(n.normalized()) : rail;
}

// The derivative of v / |v| for v moving by dv.
Eigen::Vector2d unit_rate(const Eigen::Vector2d& v, const Eigen::Vector2d& dv) {
  const double l = v.norm();
  if (!(l > 0)) return Eigen::Vector2d::Zero();
  const Eigen::Vector2d u = v / l;
  return (dv - u * u.dot(dv)) / l;
}

// A line's wheel normal at track point p (lateral_normal of the normal at p's foot) and the turning of its bisector
// with the rail's normal as the wheel moves down (the point moves up relative to it).
void line_normal(const WheelCones& wheel, const PoseFrame& f, const Eigen::Vector3d& p, const WheelNormalFoot& foot,
                 SurfaceLine& l) {
  const WheelFootNormal fn = wheel_foot_normal_rate(wheel, f, p, foot, Eigen::Vector3d::UnitZ());
  const Eigen::Vector2d v(fn.normal.y(), fn.normal.z());
  l.n = lateral_normal(fn.normal);
  l.dn = unit_rate(v, {fn.rate.y(), fn.rate.z()});
}

// The rail lines from the last one at or before the grid's first row to the first one at or after its last row
// (as far as the rail goes), each with its arc length, normal and h(x): the arcs of its segments (the deepest one
// gives the wheel's normal), or the arc through its deepest point. Kept out of line: inlined into lay_out, it made
// lay_out's own code dearer, by 0.025 % of a trajectory's instructions (bench_online section 6 at 0.2 mm).
[[gnu::noinline]]
std::vector<SurfaceLine> surface_lines(const GeometryModel& g, const LocationState& st, int side,
                                       const std::vector<double>& arc, const std::vector<SegmentInfo>& all,
                                       double s_first, double s_last) {
  const WheelCones& wheel = g.side[side].wheel;
  const RailLines& rail = g.side[side].rail;
  int rlo = rail.count(), rhi = -1;
  for (const auto& s : all) {
    rlo = std::min(rlo, s.line);
    rhi = std::max(rhi, s.line);
  }
  double S_lo = arc[static_cast<std::size_t>(rlo)], S_hi = S_lo;
  for (int r = rlo; r < rhi; ++r) S_hi += chord(rail, r);
  while (rlo > 0 && S_lo > s_first) S_lo -= chord(rail, --rlo);
  while (rhi < rail.count() - 1 && S_hi < s_last) S_hi += chord(rail, rhi++);
  std::vector<SurfaceLine> lines(static_cast<std::size_t>(rhi - rlo + 1));
  std::vector<const SegmentInfo*> deepest(lines.size(), nullptr);
  for (int r = rlo; r <= rhi; ++r) {
    SurfaceLine& l = lines[static_cast<std::size_t>(r - rlo)];
    l.S = arc[static_cast<std::size_t>(r)];
    l.y = rail.y[r];
    l.z = rail.z[r];
  }
  for (const auto& s : all) {
    const auto k = static_cast<std::size_t>(s.line - rlo);
    lines[k].h.arcs.push_back(&s);
    if (!deepest[k] || s.sagitta > deepest[k]->sagitta) deepest[k] = &s;
  }
  for (std::size_t k = 0; k < lines.size(); ++k) {
    SurfaceLine& l = lines[k];
    if (const SegmentInfo* s = deepest[k]) {
      const WheelNormalFoot foot = wheel_normal_foot(wheel, st.frame(), s->mid);  // for the bend and the normal
      fit_bend(wheel, st.frame(), *s, foot, l.h);
      line_normal(wheel, st.frame(), s->mid, foot, l);
      l.deepening = lateral_normal(s->normal).y();
      continue;
    }
    const LineApproach a = arc_through_deepest(wheel, st, l.y, l.z, l.h);
    const Eigen::Vector3d p(a.x, l.y, l.z);
    line_normal(wheel, st.frame(), p, wheel_normal_foot(wheel, st.frame(), p), l);
    l.deepening = lateral_normal(wheel_inward_normal(wheel, st.frame(), p)).y();
  }
  for (int r = rlo; r <= rhi; ++r) {
    SurfaceLine& l = lines[static_cast<std::size_t>(r - rlo)];
    const Eigen::Vector2d v = l.n + rail_normal(rail, r);
    l.n = mid_normal(l.n, rail_normal(rail, r));
    l.dn = unit_rate(v, l.dn);  // the bisector turns by half the wheel normal's turning
  }
  return lines;
}

// Rows of the grid on the lines: per row its point, normal, dh/dz and the h of its elements (linear in s between the
// two lines bracketing the row; the nearest line's beyond the rail's ends).
void lay_rows(const std::vector<SurfaceLine>& lines, const halfspace::Grid& grid, const Eigen::Vector2d& o,
              ConformalSurface& surf, std::vector<double>& deepening, std::vector<Eigen::Vector2d>& turning,
              std::vector<double>& h, std::vector<double>& gain) {
  const int ny = grid.ny;
  surf.y.resize(static_cast<std::size_t>(ny));
  surf.z.resize(static_cast<std::size_t>(ny));
  surf.normal_y.resize(static_cast<std::size_t>(ny));
  surf.normal_z.resize(static_cast<std::size_t>(ny));
  deepening.resize(static_cast<std::size_t>(ny));
  turning.resize(static_cast<std::size_t>(ny));
  h.resize(static_cast<std::size_t>(grid.size()));  // every element is written below
  gain.resize(h.size());
  // Each line's h (and normal_depth's slope) at the grid's columns, computed once (neighbouring rows share their lines).
  const auto nx = static_cast<std::size_t>(grid.nx);
  // (uninitialised: a line's row is written before it is read; zeroing both cost 1.6 % of the instructions of a
  // trajectory's rolling steps, bench_online section 6 at 0.5 mm)
  const auto line_h = std::make_unique_for_overwrite<double[]>(lines.size() * nx);
  const auto line_gain = std::make_unique_for_overwrite<double[]>(lines.size() * nx);
  std::vector<char> done(lines.size(), 0);
  std::vector<double> xs(nx);
  for (std::size_t i = 0; i < nx; ++i) xs[i] = o.x() + grid.x(static_cast<int>(i));
  auto heights = [&](std::size_t l) {
    double* row = line_h.get() + l * nx;
    if (done[l]) return row;
    done[l] = 1;
    lines[l].h.heights(xs.data(), nx, row, line_gain.get() + l * nx);
    return row;
  };
  std::size_t b = 0;
  for (int j = 0; j < ny; ++j) {
    const double s = o.y() + grid.y(j);
    while (b < lines.size() && lines[b].S <= s) ++b;  // rows ascend: the bracketing pair only moves forward
    const std::size_t a = b == 0 ? 0 : b - 1, c = std::min(b, lines.size() - 1);
    const SurfaceLine& la = lines[a];
    const SurfaceLine& lc = lines[c];
    const double t = (a == c || lc.S == la.S) ? 0.0 : std::clamp((s - la.S) / (lc.S - la.S), 0.0, 1.0);
    const auto js = static_cast<std::size_t>(j);
    surf.y[js] = (1 - t) * la.y + t * lc.y;
    surf.z[js] = (1 - t) * la.z + t * lc.z;
    const Eigen::Vector2d n = ((1 - t) * la.n + t * lc.n).normalized();
    turning[js] = unit_rate((1 - t) * la.n + t * lc.n, (1 - t) * la.dn + t * lc.dn);
    surf.normal_y[js] = n.x();
    surf.normal_z[js] = n.y();
    deepening[js] = (1 - t) * la.deepening + t * lc.deepening;
    const double* ha = heights(a);
    const double* hc = t > 0 ? heights(c) : ha;
    double* out = h.data() + static_cast<std::size_t>(grid.index(0, j));
    for (std::size_t i = 0; i < nx; ++i) out[i] = t > 0 ? (1 - t) * ha[i] + t * hc[i] : ha[i];
    const double* ga = line_gain.get() + a * nx;
    const double* gc = line_gain.get() + c * nx;
    double* g = gain.data() + static_cast<std::size_t>(grid.index(0, j));
    for (std::size_t i = 0; i < nx; ++i) g[i] = t > 0 ? (1 - t) * ga[i] + t * gc[i] : ga[i];
  }
}

// Per row of a pressure (or pressure response) field: its integral sum p dA and first moment sum p x dA (x: track x).
void row_sums(const halfspace::Grid& grid, const std::vector<double>& p, double x0, std::vector<double>& P,
              std::vector<double>& Q) {
  P.assign(static_cast<std::size_t>(grid.ny), 0.0);
  Q.assign(static_cast<std::size_t>(grid.ny), 0.0);
  const double dA = grid.element_area();
  for (int j = 0; j < grid.ny; ++j) {
    double sp = 0, sx = 0;
    for (int i = 0; i < grid.nx; ++i) {
      const double v = p[static_cast<std::size_t>(grid.index(i, j))];
      sp += v;
      sx += v * (x0 + grid.x(i));
    }
    P[static_cast<std::size_t>(j)] = sp * dA;
    Q[static_cast<std::size_t>(j)] = sx * dA;
  }
}

// Force and moment about c of row integrals P (N) and first moments Q (N m): each element pushes along its row's
// normal at (x, y_j, z_j), so row j gives n_j P_j and (X_j - c) x n_j P_j + e_x x n_j Q_j.
void row_wrench(const ConformalSurface& surf, const std::vector<double>& P, const std::vector<double>& Q,
                const Eigen::Vector3d& c, Eigen::Vector3d& F, Eigen::Vector3d& M) {
  F.setZero();
  M.setZero();
  for (int j = 0; j < surf.rows(); ++j) {
    const auto js = static_cast<std::size_t>(j);
    if (P[js] == 0 && Q[js] == 0) continue;
    const Eigen::Vector3d n = surf.normal(j);
    F += n * P[js];
    M += (surf.point(j, 0.0) - c).cross(n) * P[js] + Eigen::Vector3d::UnitX().cross(n) * Q[js];
  }
}

// The surface point at arc coordinate s (grid y) between the rows.
Eigen::Vector3d surface_point(const ConformalSurface& surf, const halfspace::Grid& grid, double x, double s) {
  const double f = std::clamp((s - grid.y0) / grid.dy, 0.0, static_cast<double>(grid.ny - 1));
  const int j = std::min(static_cast<int>(f), std::max(0, grid.ny - 2));
  const int k = std::min(j + 1, grid.ny - 1);
  const double t = f - j;
  const auto a = static_cast<std::size_t>(j), b = static_cast<std::size_t>(k);
  return {x, (1 - t) * surf.y[a] + t * surf.y[b], (1 - t) * surf.z[a] + t * surf.z[b]};
}

// The grid's row nearest to its origin: the area's reference frame.
int origin_row(const halfspace::Grid& grid) {
  return std::clamp(static_cast<int>(std::lround(-grid.y0 / grid.dy)), 0, grid.ny - 1);
}

// A surface fixed on the rail's lattice: a deeper pose differs from a shallower one only by h, so the sensitivities
// hold the surface fixed (and so do ws:wheel's predictions).
class ConformalAreaSurface final : public AreaSurface {
 public:
  const char* name() const override { return "conformal"; }

  AreaLayout lay_out(const AreaInput& in, PatchContact& pc) const override {
    const std::vector<SegmentInfo>& all = in.segments;
    const std::vector<double>& arc = in.model.rail_arc(in.side);
    std::vector<double> S(all.size());
    for (std::size_t k = 0; k < all.size(); ++k) S[k] = arc[static_cast<std::size_t>(all[k].line)];
    const Eigen::Vector2d o = surface_origin(all, S);
    AreaLayout l;
    l.frame = {Eigen::Vector3d(o.x(), o.y(), 0), Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(),
               Eigen::Vector3d::UnitY()};
    l.grid = surface_grid(in.model.options(), all, S, o, in.model.rail_lattice_origin(in.side), in.side,
                          in.located.pose());
    const halfspace::Grid& grid = l.grid;
    const auto lines = surface_lines(in.model.geometry(), in.located, in.side, arc, all, o.y() + grid.y(0),
                                     o.y() + grid.y(grid.ny - 1));
    ConformalSurface& surf = pc.conformal.emplace();
    lay_rows(lines, grid, o, surf, l.deepening, l.turning, pc.h, pc.h_gain);
    surf.x0 = o.x();
    surf.s0 = o.y();
    const int j0 = origin_row(grid);
    pc.origin = surface_point(surf, grid, o.x(), 0.0);
    pc.t1 = Eigen::Vector3d::UnitX();
    pc.t2 = surf.t2(j0);
    pc.normal = surf.normal(j0);
    l.vertical = surf.normal_z;
    return l;
  }

  // Each row's integral and first moment pushed along its normal; the normal force is the resultant's magnitude, its
  // direction the contact angle; the loaded rows give the angle range.
  void resultant(const PoseFrame& f, PatchContact& pc) const override {
    const halfspace::NormalSolution& sol = pc.solution;
    const ConformalSurface& surf = *pc.conformal;
    const Eigen::Vector3d c(0, f.y, f.z);
    std::vector<double> P, Q;
    row_sums(sol.grid, sol.pressure, surf.x0, P, Q);
    row_wrench(surf, P, Q, c, pc.force, pc.moment);
    pc.normal_force = pc.force.norm();
    const int j0 = origin_row(sol.grid);
    pc.normal = pc.normal_force > 0 ? Eigen::Vector3d(pc.force / pc.normal_force) : surf.normal(j0);
    pc.angle = contact_angle(pc.side, pc.normal);
    pc.angle_min = pc.angle_max = contact_angle(pc.side, surf.normal(j0));
    bool first = true;
    for (int j = 0; j < surf.rows(); ++j) {
      if (!(P[static_cast<std::size_t>(j)] > 0)) continue;
      const double a = contact_angle(pc.side, surf.normal(j));
      pc.angle_min = first ? a : std::min(pc.angle_min, a);
      pc.angle_max = first ? a : std::max(pc.angle_max, a);
      first = false;
    }
    // Centre of pressure on the surface (sol.cop_x, cop_y: the pressure's centroid in the unrolled coordinates).
    pc.point = sol.force > 0 ? surface_point(surf, sol.grid, surf.x0 + sol.cop_x, sol.cop_y) : pc.origin;
  }

  // Element (i, j) measures h along n_j, so a rigid motion dX = T + W x (X - c) changes it by -dX . n_j =
  // -(T . n_j + W . ((X_j - c) x n_j) + x W . (e_x x n_j)) at X = (x, y_j, z_j), times h_gain. (The Jacobian takes
  // the wheel's own normal at every element instead: area.cpp, wheel_motion.)
  void motion(const PatchContact& pc, const Pose& pose, const RigidMotion& m, std::vector<double>& dh) const override {
    const ConformalSurface& surf = *pc.conformal;
    const halfspace::Grid& grid = pc.solution.grid;
    const Eigen::Vector3d c(0, pose.y, pose.z);
    for (int j = 0; j < grid.ny; ++j) {
      const Eigen::Vector3d n = surf.normal(j);
      const double k0 = m.translation.dot(n) + m.rotation.dot((surf.point(j, 0.0) - c).cross(n));
      const double k1 = m.rotation.dot(Eigen::Vector3d::UnitX().cross(n));
      for (int i = 0; i < grid.nx; ++i) {
        const auto e = static_cast<std::size_t>(grid.index(i, j));
        dh[e] = -(k0 + k1 * (surf.x0 + grid.x(i))) * pc.h_gain[e];
      }
    }
  }

  Eigen::Vector3d element_point(const PatchContact& pc, int i, int j) const override {
    return pc.conformal->point(j, pc.conformal->x0 + pc.solution.grid.x(i));
  }

  // Each row's dP and dQ, pushed along its normal (row_wrench).
  void response(const PatchContact& pc, const Pose& pose, const halfspace::NormalResponse& r, Eigen::Vector3d& dF,
                Eigen::Vector3d& dM) const override {
    const ConformalSurface& surf = *pc.conformal;
    std::vector<double> P, Q;
    row_sums(pc.solution.grid, r.pressure, surf.x0, P, Q);
    row_wrench(surf, P, Q, Eigen::Vector3d(0, pose.y, pose.z), dF, dM);
  }

  // The rows (s, y, z, normal_y, normal_z, angle per grid row: the normals of its elements) and, with the grids, the
  // contact angle of every element.
  void describe(const PatchContact& pc, FieldSink& out) const override {
    const ConformalSurface& surf = *pc.conformal;
    const halfspace::Grid& grid = pc.solution.grid;
    std::vector<double> s(static_cast<std::size_t>(surf.rows())), angle(s.size());
    for (int j = 0; j < surf.rows(); ++j) {
      s[static_cast<std::size_t>(j)] = surf.s0 + grid.y(j);
      angle[static_cast<std::size_t>(j)] = contact_angle(pc.side, surf.normal(j));
    }
    out.begin("rows", {"", "conformal: the grid's rows across the rail profile, one value per row"});
    out.numbers("s", s.data(), s.size(), {"m", "arc length of the row along the rail profile (from its first line)"});
    out.numbers("y", surf.y.data(), surf.y.size(), {"m", "y of the row's reference point on the rail surface (track frame)"});
    out.numbers("z", surf.z.data(), surf.z.size(), {"m", "z of the row's reference point on the rail surface (track frame)"});
    out.numbers("normal_y", surf.normal_y.data(), surf.normal_y.size(),
                {"-", "y component of the row's unit normal from the rail into the wheel"});
    out.numbers("normal_z", surf.normal_z.data(), surf.normal_z.size(),
                {"-", "z component of the row's unit normal from the rail into the wheel"});
    out.numbers("angle", angle.data(), angle.size(), {"rad", "contact angle of the row's normal"});
    out.end();
    if (pc.solution.pressure.empty()) return;
    std::vector<double> grid_angle(static_cast<std::size_t>(grid.size()));
    for (int j = 0; j < grid.ny; ++j)
      std::fill_n(grid_angle.begin() + static_cast<std::ptrdiff_t>(grid.index(0, j)), grid.nx,
                  angle[static_cast<std::size_t>(j)]);
    out.grid("angles", grid_angle.data(), grid.nx, grid.ny, {"rad", "conformal: contact angle of each element (its row's)"});
  }
};

const ConformalAreaSurface kConformal;

}  // namespace

const AreaSurface& conformal_surface() { return kConformal; }
void row_turning(const ContactModel& model, const Pose& pose, const PatchContact& pc, int coordinate,
                 std::vector<Eigen::Vector3d>& dn) {
  const ConformalSurface& surf = *pc.conformal;
  const halfspace::Grid& g = pc.solution.grid;
  const WheelCones& wheel = model.geometry().side[static_cast<std::size_t>(pc.side)].wheel;
  std::vector<double> P, Q;
  row_sums(g, pc.solution.pressure, surf.x0, P, Q);
  const PoseFrame f0(pose);
  const RigidMotion m = pose_motion(pose, coordinate);
  const Eigen::Vector3d c(0, pose.y, pose.z);
  dn.assign(static_cast<std::size_t>(g.ny), Eigen::Vector3d::Zero());
  for (int j = 0; j < g.ny; ++j) {
    const auto js = static_cast<std::size_t>(j);
    const double x = P[js] > 0 ? Q[js] / P[js] : surf.x0;
    const Eigen::Vector3d X = surf.point(j, x), n = surf.normal(j);
    // The wheel's normal at X turns with the wheel (W x n) and as X moves relative to it, by -(T + W x (X - c)).
    const WheelFootNormal fn = wheel_foot_normal_rate(wheel, f0, X, -(m.translation + m.rotation.cross(X - c)));
    const Eigen::Vector3d dw = m.rotation.cross(fn.normal) + fn.rate;
    const Eigen::Vector2d v(fn.normal.y(), fn.normal.z()), nw = v.normalized();  // x component dropped
    const Eigen::Vector2d n2(n.y(), n.z()), nr = 2 * nw.dot(n2) * n2 - nw;      // the rail's: n bisects it and nw
    const Eigen::Vector2d d = unit_rate(nr + nw, unit_rate(v, {dw.y(), dw.z()}));
    dn[js] = {0.0, d.x(), d.y()};
  }
}

void turning_wrench(const PatchContact& pc, const Pose& pose, const std::vector<Eigen::Vector3d>& dn,
                    Eigen::Vector3d& dF, Eigen::Vector3d& dM) {
  const ConformalSurface& surf = *pc.conformal;
  std::vector<double> P, Q;
  row_sums(pc.solution.grid, pc.solution.pressure, surf.x0, P, Q);
  const Eigen::Vector3d c(0, pose.y, pose.z);
  dF.setZero();
  dM.setZero();
  for (int j = 0; j < surf.rows(); ++j) {
    const auto js = static_cast<std::size_t>(j);
    dF += dn[js] * P[js];
    dM += (surf.point(j, 0.0) - c).cross(dn[js]) * P[js] + Eigen::Vector3d::UnitX().cross(dn[js]) * Q[js];
  }
}

ConformalLayoutAt conformal_layout_at(const ContactModel& model, const LocationState& st, const PatchContact& pc) {
  const ConformalSurface& surf = *pc.conformal;
  const halfspace::Grid& g = pc.solution.grid;
  const double lo = surf.s0 + g.y(0) - 0.5 * g.dy, hi = surf.s0 + g.y(g.ny - 1) + 0.5 * g.dy;
  const std::vector<double>& arc = model.rail_arc(pc.side);
  ConformalLayoutAt out;
  out.h.assign(static_cast<std::size_t>(g.size()), NAN);
  out.origin.setConstant(NAN);
  // The side's patches with a segment on the area's rows, laid out together as the area was.
  std::vector<int> patches;
  std::vector<SegmentInfo> all;
  for (int p = 0; p < static_cast<int>(st.patches(pc.side).size()); ++p) {
    std::vector<SegmentInfo> segs;
    collect_segments(model.geometry(), st, pc.side, st.patches(pc.side)[static_cast<std::size_t>(p)], segs);
    const bool on_rows = std::any_of(segs.begin(), segs.end(), [&](const SegmentInfo& x) {
      const double S = arc[static_cast<std::size_t>(x.line)];
      return S >= lo && S <= hi;
    });
    if (!on_rows) continue;
    patches.push_back(p);
    all.insert(all.end(), segs.begin(), segs.end());
  }
  if (patches.empty()) return out;
  const AreaInput in{model, st, pc.side, patches, all, st.patches(pc.side)[static_cast<std::size_t>(patches.front())]};
  PatchContact moved;
  moved.side = pc.side;
  const AreaLayout l = kConformal.lay_out(in, moved);
  const ConformalSurface& ms = *moved.conformal;
  out.origin = {ms.x0, ms.s0};
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {  // the same lattice element in the moved layout's grid
      const double x = surf.x0 + g.x(i) - ms.x0, s = surf.s0 + g.y(j) - ms.s0;
      const long a = std::lround((x - l.grid.x0) / l.grid.dx), b = std::lround((s - l.grid.y0) / l.grid.dy);
      if (a < 0 || b < 0 || a >= l.grid.nx || b >= l.grid.ny) continue;
      out.h[static_cast<std::size_t>(g.index(i, j))] =
          moved.h[static_cast<std::size_t>(l.grid.index(static_cast<int>(a), static_cast<int>(b)))];
    }
  return out;
}

}  // namespace areas
}  // namespace wrc
