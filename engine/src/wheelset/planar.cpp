// The planar surface (surface.hpp): one plane per area, the paper's (wrc/wheelset/contact.hpp says how the plane, the
// grid and h are made; docs/design.md section 3).
#include "surface.hpp"

#include "wrc/geometry/wheel_surface.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace wrc::areas {
namespace {

// The potential contact area: a grid aligned with the plane origin covering the projected segments plus the margin.
halfspace::Grid area_grid(const ContactOptions& opt, const std::vector<SegmentInfo>& all, const Plane& pl, int side,
                        const Pose& pose) {
  const auto [umin, umax, vmin, vmax] = projected_bounds(all, pl);
  return span_grid(opt, index_span(umin, umax, opt.element, opt.margin), index_span(vmin, vmax, opt.element, opt.margin),
                   all, side, pose);
}

// The rail lines across the grid's lateral range (one beyond each side when the rail has it), projected on the
// plane and ordered across it, each with its h(x): the arcs of its segments, or the arc through its deepest point.
std::vector<LineProfile> line_profiles(const GeometryModel& g, const LocationState& st, int side,
                                       const std::vector<SegmentInfo>& all, const std::vector<WheelNormalFoot>& feet,
                                       const Plane& pl, const halfspace::Grid& grid) {
  const WheelCones& wheel = g.side[side].wheel;
  const RailLines& rail = g.side[side].rail;
  int rmin = rail.count(), rmax = -1;
  for (const auto& s : all) {
    rmin = std::min(rmin, s.line);
    rmax = std::max(rmax, s.line);
  }
  auto v_of = [&](int r) { return (Eigen::Vector3d(0, rail.y[r], rail.z[r]) - pl.O).dot(pl.t2); };
  int rlo = rmin, rhi = rmax;
  while (rlo > 0 && v_of(rlo) > grid.y0) --rlo;
  while (rhi < rail.count() - 1 && v_of(rhi) < grid.y(grid.ny - 1)) ++rhi;
  std::vector<LineProfile> lines(static_cast<std::size_t>(rhi - rlo + 1));
  for (int r = rlo; r <= rhi; ++r) {
    LineProfile& lp = lines[static_cast<std::size_t>(r - rlo)];
    const Eigen::Vector3d d(0, rail.y[r], rail.z[r]);
    lp.v = (d - pl.O).dot(pl.t2);
    lp.u0 = (d - pl.O).dot(pl.t1);
  }
  for (const auto& s : all) lines[static_cast<std::size_t>(s.line - rlo)].arcs.push_back(&s);
  for (int r = rlo; r <= rhi; ++r) {
    LineProfile& lp = lines[static_cast<std::size_t>(r - rlo)];
    if (lp.arcs.empty()) {
      arc_through_deepest(wheel, st, rail.y[r], rail.z[r], lp);
      continue;
    }
    const SegmentInfo* deepest = lp.arcs.front();
    for (const SegmentInfo* s : lp.arcs)
      if (s->sagitta > deepest->sagitta) deepest = s;
    fit_bend(wheel, st.frame(), *deepest, feet[static_cast<std::size_t>(deepest - all.data())], lp);
  }
  // The projected lines must be ordered across the plane (they are, unless the plane is far off the rail).
  std::stable_sort(lines.begin(), lines.end(), [](const LineProfile& a, const LineProfile& b) { return a.v < b.v; });
  return lines;
}

// h at the element centres: along each projected line its arcs, linear in v between the two lines bracketing
// the element. A line's track x at column i is (u_i - u0) / t1x (t1 is the track's x turned into the plane: t1x > 0),
// ascending with i: each line's h is walked along its columns (walked_heights) and kept for the next row, since rows
// ascend in v and the bracketing pair only moves forward.
std::vector<double> undeformed_distance(const std::vector<LineProfile>& lines, const Plane& pl,
                                        const halfspace::Grid& grid, std::vector<double>& gain) {
  std::vector<double> vs(lines.size());
  for (std::size_t k = 0; k < lines.size(); ++k) vs[k] = lines[k].v;
  const double t1x = pl.t1.x();  // u = x t1x + u0 along a line
  const auto nx = static_cast<std::size_t>(grid.nx);
  std::vector<double> h(static_cast<std::size_t>(grid.size()), 0.0);
  gain.assign(h.size(), 1.0);
  // Two lines' h and slope at the columns: [0, nx) h, [nx, 2 nx) slope, per slot; `held` the line each slot holds.
  std::vector<double> xs(nx), slots(4 * nx);
  std::array<std::size_t, 2> held{SIZE_MAX, SIZE_MAX};
  const auto line_at = [&](std::size_t l) {
    if (held[0] == l) return slots.data();
    if (held[1] == l) return slots.data() + 2 * nx;
    const std::size_t slot = held[0] == SIZE_MAX || (held[1] != SIZE_MAX && held[0] < held[1]) ? 0 : 1;  // the one behind
    double* out = slots.data() + 2 * slot * nx;
    const LineProfile& lp = lines[l];
    for (std::size_t i = 0; i < nx; ++i) xs[i] = (grid.x(static_cast<int>(i)) - lp.u0) / t1x;
    lp.walked_heights(xs.data(), nx, out, out + nx);
    held[slot] = l;
    return out;
  };
  for (int j = 0; j < grid.ny; ++j) {
    const double v = grid.y(j);
    const auto it = std::upper_bound(vs.begin(), vs.end(), v);
    std::size_t b = static_cast<std::size_t>(it - vs.begin());
    const std::size_t a = b == 0 ? 0 : b - 1;
    b = std::min(b, vs.size() - 1);
    const LineProfile& la = lines[a];
    const LineProfile& lb = lines[b];
    const double t = (a == b || lb.v == la.v) ? 0.0 : std::clamp((v - la.v) / (lb.v - la.v), 0.0, 1.0);
    const double* ha = line_at(a);
    const double* hb = t > 0 ? line_at(b) : nullptr;
    double* hj = h.data() + static_cast<std::size_t>(grid.index(0, j));
    double* gj = gain.data() + static_cast<std::size_t>(grid.index(0, j));
    // Without a second line its terms are t times normal_depth(0, 0) = 0 and normal_depth_slope(0, 0) = 1.
    for (std::size_t i = 0; i < nx; ++i) {
      hj[i] = (1 - t) * ha[i] + t * (hb ? hb[i] : 0.0);
      gj[i] = (1 - t) * ha[nx + i] + t * (hb ? hb[nx + i] : 1.0);
    }
  }
  return h;
}

// The rigid motion's terms of a plane (pressure acts along its one normal n at plane point X): dX = T + W x (X - c)
// changes h by -dX . n = -(k0 + ku u + kv v) in plane coordinates (u, v).
// The rigid motion's terms of a plane (pressure acts along its one normal n at plane point X): dX = T + W x (X - c)
// changes h by -dX . n = -(k0 + ku u + kv v) in plane coordinates (u, v).
struct PlaneLever {
  Eigen::Vector3d oc, t1n, t2n;  // (O - c) x n, t1 x n, t2 x n
  double k0 = 0, ku = 0, kv = 0; // T . n + W . oc, W . t1n, W . t2n
  PlaneLever(const PatchContact& pc, const Pose& pose, const RigidMotion& m = {}) {
    const Eigen::Vector3d c(0, pose.y, pose.z);
    oc = (pc.origin - c).cross(pc.normal);
    t1n = pc.t1.cross(pc.normal);
    t2n = pc.t2.cross(pc.normal);
    k0 = m.translation.dot(pc.normal) + m.rotation.dot(oc), ku = m.rotation.dot(t1n), kv = m.rotation.dot(t2n);
  }
};

// The plane is held fixed in the sensitivities: exact to first order for the elastic stiffness, which dominates while
// the contact does not slide along a curved profile.
class PlanarAreaSurface final : public AreaSurface {
 public:
  const char* name() const override { return "planar"; }

  AreaLayout lay_out(const AreaInput& in, PatchContact& pc) const override {
    const WheelCones& wheel = in.model.geometry().side[in.side].wheel;
    const auto feet = mid_feet(wheel, in.located.frame(), in.segments);  // for the plane and the lines' bends
    const Plane pl = foot_plane_of(wheel, in.located.frame(), in.segments, feet, in.first);
    pc.origin = pl.O;
    pc.normal = pl.n;
    pc.t1 = pl.t1;
    pc.t2 = pl.t2;
    AreaLayout l;
    l.grid = area_grid(in.model.options(), in.segments, pl, in.side, in.located.pose());
    const auto lines = line_profiles(in.model.geometry(), in.located, in.side, in.segments, feet, pl, l.grid);
    pc.h = undeformed_distance(lines, pl, l.grid, pc.h_gain);
    l.frame = pl;
    l.vertical.assign(static_cast<std::size_t>(l.grid.ny), pl.n.z());  // one normal: h deepens by its z part
    l.deepening = l.vertical;
    return l;
  }

  void resultant(const PoseFrame& f, PatchContact& pc) const override {
    const halfspace::NormalSolution& sol = pc.solution;
    const Eigen::Vector3d c(0, f.y, f.z);
    pc.normal_force = sol.force;
    pc.force = sol.force * pc.normal;
    pc.point = pc.origin + sol.cop_x * pc.t1 + sol.cop_y * pc.t2;
    pc.moment = (pc.point - c).cross(pc.force);
    pc.angle = contact_angle(pc.side, pc.normal);
    pc.angle_min = pc.angle_max = pc.angle;  // one plane: the pressure acts along one normal
  }

  void motion(const PatchContact& pc, const Pose& pose, const RigidMotion& m, std::vector<double>& dh) const override {
    const halfspace::Grid& grid = pc.solution.grid;
    const PlaneLever k(pc, pose, m);
    for (int j = 0; j < grid.ny; ++j)
      for (int i = 0; i < grid.nx; ++i) {
        const auto e = static_cast<std::size_t>(grid.index(i, j));
        dh[e] = -(k.k0 + k.ku * grid.x(i) + k.kv * grid.y(j)) * pc.h_gain[e];
      }
  }

  Eigen::Vector3d element_point(const PatchContact& pc, int i, int j) const override {
    return pc.origin + pc.solution.grid.x(i) * pc.t1 + pc.solution.grid.y(j) * pc.t2;
  }

  // dF = n dN; dM from the response's force and first moments (normal.hpp).
  void response(const PatchContact& pc, const Pose& pose, const halfspace::NormalResponse& r, Eigen::Vector3d& dF,
                Eigen::Vector3d& dM) const override {
    const PlaneLever k(pc, pose);
    dM = k.oc * r.force + k.t1n * r.moment_x + k.t2n * r.moment_y;
    dF = pc.normal * r.force;
  }

  void describe(const PatchContact&, FieldSink&) const override {}  // its frame is the plane: no fields of its own
};

const PlanarAreaSurface kPlanar;

}  // namespace

const AreaSurface& planar_surface() { return kPlanar; }

}  // namespace wrc::areas
