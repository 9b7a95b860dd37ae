// Contact location: every search against brute force, segments against an independent numerical reference,
// line-level degenerate cases, patches, threads and errors. (S1002 / 60E1 themselves are Lua definitions: see
// tests/scripts/strategy_*.lua and geometry_rigid.lua; bench_contact_location checks them at 0.1 mm.)
#include "geometry_fixtures.hpp"
#include "reference_solid.hpp"
#include "wrc/core/error.hpp"
#include "wrc/geometry/location.hpp"
#include "approx.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <thread>
#include <vector>

using wrc::test::within_abs;
using wrc::test::within_rel;
using namespace wrc;

namespace {

using Scan = NativePlan::Scan;

// Same patches and segments (lines, cones, ends within 1e-9 m).
std::string difference(const LocationState& a, const LocationState& b) {
  for (int s : {kLeft, kRight}) {
    if (a.patches(s).size() != b.patches(s).size())
      return fmt::format("{} side: {} patches vs {}", side_name(s), a.patches(s).size(), b.patches(s).size());
    if (a.segments(s).size() != b.segments(s).size())
      return fmt::format("{} side: {} segments vs {}", side_name(s), a.segments(s).size(), b.segments(s).size());
    for (std::size_t i = 0; i < a.segments(s).size(); ++i) {
      const Segment &x = a.segments(s)[i], &y = b.segments(s)[i];
      if (x.line != y.line || x.cone_t != y.cone_t || x.cone_l != y.cone_l || std::abs(x.x_t - y.x_t) > 1e-9 ||
          std::abs(x.x_l - y.x_l) > 1e-9)
        return fmt::format("{} side, segment {}: line {} [{}, {}] cones {}/{} vs line {} [{}, {}] cones {}/{}",
                           side_name(s), i, x.line, x.x_t, x.x_l, x.cone_t, x.cone_l, y.line, y.x_t, y.x_l, y.cone_t,
                           y.cone_l);
    }
    for (std::size_t i = 0; i < a.patches(s).size(); ++i)
      if (a.patches(s)[i].first_segment != b.patches(s)[i].first_segment ||
          a.patches(s)[i].segment_count != b.patches(s)[i].segment_count ||
          a.patches(s)[i].longest != b.patches(s)[i].longest)
        return fmt::format("{} side: patch {} groups other segments", side_name(s), i);
  }
  return {};
}

struct Coverage {
  int poses = 0, patches = 0, two_patch_sides = 0, two_segment_lines = 0, two_cone_segments = 0, yawed = 0;
};

// Runs `poses` random poses; every plan must agree with brute force on every pose.
Coverage compare_with_brute(const GeometryModel& m, int poses, unsigned seed) {
  std::mt19937_64 rng(seed);
  NativeSearch brute({false, Scan::test});
  const NativePlan plans[] = {{false, Scan::walk}, {true, Scan::test}, {true, Scan::walk}};
  const char* names[] = {"walk", "coarse+test", "coarse+walk"};
  LocationState ref, st;
  Coverage cov;
  for (int k = 0; k < poses; ++k) {
    const Pose p = test::random_pose(rng, *m.track, test::log_uniform(rng, 1e-6, 1e-3));
    locate_contact(m, p, ref, brute);
    for (int q = 0; q < 3; ++q) {
      NativeSearch s(plans[q]);
      locate_contact(m, p, st, s);
      const std::string diff = difference(ref, st);
      INFO("pose ", k, ": y = ", p.y, ", z = ", p.z, ", roll = ", p.roll, ", yaw = ", p.yaw, "; ", names[q]);
      REQUIRE(diff == "");
      if (q > 0) CHECK(st.counters(kLeft).tests + st.counters(kRight).tests < ref.counters(kLeft).tests);
    }
    ++cov.poses;
    if (std::abs(p.yaw) > 1e-3) ++cov.yawed;
    for (int s : {kLeft, kRight}) {
      cov.patches += static_cast<int>(ref.patches(s).size());
      if (ref.patches(s).size() >= 2) ++cov.two_patch_sides;
      const auto& segs = ref.segments(s);
      for (std::size_t i = 0; i < segs.size(); ++i) {
        if (segs[i].cone_t != segs[i].cone_l) ++cov.two_cone_segments;
        if (i > 0 && segs[i].line == segs[i - 1].line) ++cov.two_segment_lines;
      }
    }
  }
  return cov;
}

}  // namespace

TEST_CASE("every search finds what brute force finds: synthetic S1002-like pair, 2000 poses") {
  const auto m = test::make_model(test::synthetic_wheel(1e-3), test::synthetic_rail(1e-3), 4, 4e-3);
  const Coverage c = compare_with_brute(m, 2000, 7);
  MESSAGE("synthetic pair: ", c.poses, " poses, ", c.patches, " patches, ", c.two_patch_sides,
          " sides with two patches, ", c.two_cone_segments, " segments between two cones, ", c.yawed, " yawed poses");
  CHECK(c.patches > 0.9 * c.poses);  // the depth is set ignoring yaw: a few of the shallowest poses lose contact
  CHECK(c.two_patch_sides > 10);
  CHECK(c.two_cone_segments > 1000);
}

TEST_CASE("every search finds what brute force finds: the awkward pair, 2000 poses") {
  // Hollow tread, exact cylinder, vertical step and vertical flange back on the wheel; two crowns on the rail.
  const auto m = test::make_model(test::awkward_wheel(), test::awkward_rail(1e-3), 4, 4e-3);
  const Coverage c = compare_with_brute(m, 2000, 11);
  MESSAGE("awkward pair: ", c.poses, " poses, ", c.patches, " patches, ", c.two_patch_sides,
          " sides with two patches, ", c.two_segment_lines, " lines with two segments, ", c.two_cone_segments,
          " segments between two cones");
  CHECK(c.two_patch_sides > 100);
  CHECK(c.two_segment_lines > 0);
  CHECK(c.two_cone_segments > 300);
}

TEST_CASE("segments agree with an independent numerical reference (grid + bisection on the polyline solid)") {
  for (int pair = 0; pair < 2; ++pair) {
    const auto m = pair == 0 ? test::make_model(test::synthetic_wheel(1e-3), test::synthetic_rail(1e-3))
                             : test::make_model(test::awkward_wheel(), test::awkward_rail(1e-3));
    std::mt19937_64 rng(3 + pair);
    NativeSearch brute({false, Scan::test});
    LocationState st;
    int compared = 0;
    double worst = 0;
    for (int k = 0; k < 24; ++k) {
      const Pose p = test::random_pose(rng, *m.track, test::log_uniform(rng, 1e-5, 1e-3));
      locate_contact(m, p, st, brute);
      const PoseFrame f(p);
      for (int s : {kLeft, kRight}) {
        const WheelCones& w = m.side[s].wheel;
        const test::RefSolid solid{w, 1, static_cast<int>(w.y.size()) - 2};
        // The engine's segments by line.
        std::vector<std::vector<std::pair<double, double>>> by_line(m.side[s].rail.count());
        for (const Segment& g : st.segments(s)) by_line[g.line].emplace_back(g.x_t, g.x_l);
        for (int r = 0; r < m.side[s].rail.count(); ++r) {
          if (by_line[r].empty() && (r % 8)) continue;  // lines without segments: a sample of them
          const auto ref = test::reference_segments(solid, f, m.side[s].rail.y[r], m.side[s].rail.z[r]);
          // Segments shorter than the grid step can hide from the reference; compare the others.
          std::vector<std::pair<double, double>> eng;
          for (auto e : by_line[r])
            if (e.second - e.first > 3e-4) eng.push_back(e);
          std::vector<std::pair<double, double>> rf;
          for (auto e : ref)
            if (e.second - e.first > 3e-4) rf.push_back(e);
          INFO("pair ", pair, " pose ", k, " side ", s, " line ", r);
          REQUIRE(eng.size() == rf.size());
          for (std::size_t i = 0; i < eng.size(); ++i) {
            worst = std::max({worst, std::abs(eng[i].first - rf[i].first), std::abs(eng[i].second - rf[i].second)});
            CHECK(std::abs(eng[i].first - rf[i].first) < 1e-9);
            CHECK(std::abs(eng[i].second - rf[i].second) < 1e-9);
            ++compared;
          }
        }
      }
    }
    MESSAGE("pair ", pair, ": ", compared, " segments compared, worst end difference ", worst, " m");
    CHECK(compared > 100);
  }
}

namespace {

// A one-side test model: the given wheel generatrix points and rail points placed directly (wheelset / track frame).
GeometryModel direct_model(std::vector<double> wy, std::vector<double> wz, std::vector<double> ry,
                           std::vector<double> rz) {
  GeometryModel m;
  for (int s : {kLeft, kRight}) {
    WheelCones w;
    w.y = {wy.front()};
    w.z = {0.0};
    w.y.insert(w.y.end(), wy.begin(), wy.end());
    w.z.insert(w.z.end(), wz.begin(), wz.end());
    w.y.push_back(wy.back());
    w.z.push_back(0.0);
    w.r2.resize(w.y.size());
    for (std::size_t i = 0; i < w.y.size(); ++i) w.r2[i] = w.z[i] * w.z[i];
    w.r2_range.build(w.r2);
    m.side[s].wheel = w;
    m.side[s].rail.y = ry;
    m.side[s].rail.z = rz;
    m.side[s].wheel_r2_max = *std::max_element(w.r2.begin(), w.r2.end());
  }
  m.strategy.name = "test";
  return m;
}

}  // namespace

TEST_CASE("line-level degenerate cases") {
  NativeSearch brute({false, Scan::test}), walk({false, Scan::walk});
  LocationState st;
  SUBCASE("zero yaw and roll, line exactly at a shared generatrix point: one segment, on the cone before it") {
    // Points at y = 0.74, 0.75, 0.76 with radii 0.45, 0.46, 0.455; the line at y = 0.75, z = -0.455.
    const auto m = direct_model({0.74, 0.75, 0.76}, {-0.45, -0.46, -0.455}, {0.75}, {-0.455});
    for (PoseSearch* s : {static_cast<PoseSearch*>(&brute), static_cast<PoseSearch*>(&walk)}) {
      locate_contact(m, Pose{}, st, *s);
      REQUIRE(st.segments(kLeft).size() == 1);
      const Segment& g = st.segments(kLeft)[0];
      const double x = std::sqrt(0.46 * 0.46 - 0.455 * 0.455);
      CHECK(g.x_t == within_rel(-x, 1e-14));
      CHECK(g.x_l == within_rel(x, 1e-14));
      CHECK(g.cone_t == 1);  // cone 1 joins points 0.74 and 0.75 (cone 0 is the closing disc)
      CHECK(g.cone_l == 1);
    }
  }
  SUBCASE("zero yaw, line in the plane of a flat ring: the ring is skipped, the cone ending there counts") {
    // A vertical step at y = 0.75 from radius 0.46 down to 0.45; the line at y = 0.75 exactly, z = -0.455.
    const auto m = direct_model({0.74, 0.75, 0.75, 0.76}, {-0.46, -0.46, -0.45, -0.45}, {0.75}, {-0.455});
    locate_contact(m, Pose{}, st, brute);
    REQUIRE(st.segments(kLeft).size() == 1);
    const double x = std::sqrt(0.46 * 0.46 - 0.455 * 0.455);  // the limit from y < 0.75 (radius 0.46)
    CHECK(st.segments(kLeft)[0].x_l == within_rel(x, 1e-14));
    // Yawed, the same line crosses the ring's plane once: entry through the ring, exit through a cone.
    locate_contact(m, Pose{0, 0, 0, 0.01}, st, brute);
    REQUIRE(st.segments(kLeft).size() == 1);
    const Segment& g = st.segments(kLeft)[0];
    CHECK(g.cone_t != g.cone_l);
    CHECK((g.cone_t == 2 || g.cone_l == 2));  // cone 2 is the ring
  }
  SUBCASE("a line leaving through the closed end face (yaw): even count, one end on the end disc") {
    // A short cylinder 0.70 .. 0.80 of radius 0.45; yaw makes the line at y = 0.7997 (1 mm inside, so 30 mm long
    // in x, 0.6 mm in y at 20 mrad) leave through the disc at 0.80.
    const auto m = direct_model({0.70, 0.80}, {-0.45, -0.45}, {0.7997}, {-0.449});
    for (PoseSearch* s : {static_cast<PoseSearch*>(&brute), static_cast<PoseSearch*>(&walk)}) {
      locate_contact(m, Pose{0, 0, 0, 0.02}, st, *s);
      REQUIRE(st.segments(kLeft).size() == 1);
      const Segment& g = st.segments(kLeft)[0];
      const int end_disc = m.side[kLeft].wheel.cone_count() - 1;
      CHECK((g.cone_t == end_disc || g.cone_l == end_disc));
      CHECK(g.length() > 0);
      // The end on the disc lies in its plane y_w = 0.80.
      const PoseFrame f(Pose{0, 0, 0, 0.02});
      const double x_disc = g.cone_t == end_disc ? g.x_t : g.x_l;
      CHECK(f.to_wheelset({x_disc, 0.7997, -0.449}).y() == within_rel(0.80, 1e-13));
    }
  }
  SUBCASE("tangent line (d = 0): a zero-length segment, reported as the conditions d >= 0 say") {
    const auto m = direct_model({0.70, 0.80}, {-0.45, -0.45}, {0.75}, {-0.45});
    locate_contact(m, Pose{}, st, brute);
    REQUIRE(st.segments(kLeft).size() == 1);
    CHECK(st.segments(kLeft)[0].length() == 0);
    REQUIRE(st.patches(kLeft).size() == 1);
  }
  SUBCASE("a yawed line through a shared circle (graze or crossing): never an odd count") {
    // Sweep the line's height across the radius of the shared point of two cones, yawed so that the line meets
    // the circle's plane near it: every count stays even (the shared-circle rule of location.cpp).
    const auto m0 = direct_model({0.70, 0.75, 0.80}, {-0.45, -0.452, -0.449}, {0.75}, {-0.452});
    for (int k = -50; k <= 50; ++k) {
      auto m = m0;
      m.side[kLeft].rail.z[0] = -0.452 + k * 1e-16;
      CHECK_NOTHROW(locate_contact(m, Pose{0, 0, 0, 1e-3}, st, brute));
    }
  }
}

TEST_CASE("patches: connectivity, two-point contact, nominal point and normal") {
  const auto m = test::make_model(test::awkward_wheel(), test::awkward_rail(0.2e-3));
  NativeSearch walk({false, Scan::walk});
  LocationState st;
  std::mt19937_64 rng(5);
  int two_point = 0;
  for (int k = 0; k < 200; ++k) {
    const Pose p = test::random_pose(rng, *m.track, test::log_uniform(rng, 1e-5, 5e-4));
    locate_contact(m, p, st, walk);
    for (int s : {kLeft, kRight}) {
      const auto& segs = st.segments(s);
      const auto& patches = st.patches(s);
      if (patches.size() >= 2) ++two_point;
      int total = 0;
      for (std::size_t q = 0; q < patches.size(); ++q) {
        const Patch& pa = patches[q];
        total += pa.segment_count;
        // Segments of a patch: connected through overlapping neighbours; the longest one gives the point.
        double longest = 0;
        for (int i = pa.first_segment; i < pa.first_segment + pa.segment_count; ++i) longest = std::max(longest, segs[i].length());
        const Segment& L = segs[pa.longest];
        CHECK(L.length() == longest);
        CHECK(pa.point.x() == within_rel(0.5 * (L.x_t + L.x_l), 1e-5));
        CHECK(pa.point.y() == L.y);
        CHECK(pa.point.z() == L.z);
        CHECK(pa.normal.norm() == within_rel(1.0, 1e-12));
        CHECK(pa.normal.z() < 0);  // the wheel's outward normal at a rail contact points down, toward the rail
        CHECK(pa.depth >= -1e-12);  // the nominal point is inside the wheel
        for (int i = pa.first_segment + 1; i < pa.first_segment + pa.segment_count; ++i)
          CHECK(std::make_pair(segs[i].line, segs[i].x_t) > std::make_pair(segs[i - 1].line, segs[i - 1].x_t));
        // Different patches never touch: no overlapping segments on adjacent lines.
        for (std::size_t o = q + 1; o < patches.size(); ++o)
          for (int i = pa.first_segment; i < pa.first_segment + pa.segment_count; ++i)
            for (int j = patches[o].first_segment; j < patches[o].first_segment + patches[o].segment_count; ++j)
              if (std::abs(segs[i].line - segs[j].line) == 1)
                CHECK((segs[i].x_l < segs[j].x_t || segs[j].x_l < segs[i].x_t));
      }
      CHECK(total == static_cast<int>(segs.size()));
    }
  }
  CHECK(two_point > 10);
}

TEST_CASE("the coarse wheel contains the fine wheel dilated by the cells' size (checked by sampling)") {
  const Profile wheel = test::awkward_wheel();
  for (double D : {1e-4, 5e-4, 2e-3}) {
    const Profile coarse = offset_outward(wheel, D, 2e-3);
    // Points of the dilated solid: random points within D of a random point of the profile polyline, plus points
    // of the solid itself just above the profile (the wheel solid lies at z >= profile in its own frame).
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> U(0, 1);
    auto coarse_z = [&](double y) {  // the coarse polyline (lower boundary of the coarse solid) at y
      for (std::size_t i = 0; i + 1 < coarse.size(); ++i)
        if (coarse.y[i] <= y && y <= coarse.y[i + 1])
          return coarse.z[i] + (y - coarse.y[i]) / (coarse.y[i + 1] - coarse.y[i]) * (coarse.z[i + 1] - coarse.z[i]);
      return 1e9;  // outside the coarse range: fails below
    };
    double worst = -1;
    for (int k = 0; k < 20000; ++k) {
      const std::size_t i = static_cast<std::size_t>(U(rng) * (wheel.size() - 1));
      const double t = U(rng);
      const double py = wheel.y[i] + t * (wheel.y[i + 1] - wheel.y[i]), pz = wheel.z[i] + t * (wheel.z[i + 1] - wheel.z[i]);
      const double a = 2 * M_PI * U(rng), r = D * std::sqrt(U(rng));
      const double qy = py + r * std::cos(a), qz = pz + r * std::sin(a);
      worst = std::max(worst, coarse_z(qy) - qz);  // must be <= 0: the point is above the coarse lower boundary
    }
    CHECK(worst <= 0);
  }
  // build_geometry refuses a coarse wheel that does not enclose the dilation.
  auto track = test::make_track(test::synthetic_wheel(1e-3), test::synthetic_rail(1e-3));
  SideDiscretisation d;
  d.wheel = test::synthetic_wheel(1e-3);
  d.rail = test::synthetic_rail(1e-3);
  d.coarse_every = 8;
  d.coarse_wheel = test::synthetic_wheel(2e-3);  // not offset at all
  CHECK_THROWS_WITH_AS(build_geometry(track, {d, d}), doctest::Contains("does not contain the fine wheel dilated"),
                       Error);
  d.coarse_wheel = offset_outward(d.wheel, cell_dilation(d.rail, 8), 2e-3);
  CHECK_NOTHROW(build_geometry(track, {d, d}));
}

TEST_CASE("model: closed wheel, ordered lines, cone data, constant-slope resampling") {
  const auto m = test::make_model(test::synthetic_wheel(1e-3), test::synthetic_rail(1e-3), 8);
  for (int s : {kLeft, kRight}) {
    const WheelCones& w = m.side[s].wheel;
    CHECK(w.z.front() == 0);
    CHECK(w.z.back() == 0);
    CHECK(w.y.front() == w.y[1]);
    CHECK(w.y.back() == w.y[w.y.size() - 2]);
    CHECK(std::is_sorted(w.y.begin(), w.y.end()));
    CHECK(std::is_sorted(m.side[s].rail.y.begin(), m.side[s].rail.y.end()));
    CHECK(m.side[s].coarse->dilation == within_rel(cell_dilation(test::synthetic_rail(1e-3), 8), 1e-5));
    // Every fine line belongs to exactly one cell, within `dilation` of its coarse line.
    const CoarseLevel& c = *m.side[s].coarse;
    int covered = 0;
    for (std::size_t k = 0; k < c.cell_first.size(); ++k) {
      for (int r = c.cell_first[k]; r <= c.cell_last[k]; ++r) {
        ++covered;
        CHECK(std::hypot(m.side[s].rail.y[r] - c.lines.y[k], m.side[s].rail.z[r] - c.lines.z[k]) <= c.dilation + 1e-15);
      }
    }
    CHECK(covered == m.side[s].rail.count());
  }
  // Mirror images.
  CHECK(m.side[kLeft].wheel.y[5] == within_rel(-m.side[kRight].wheel.y[m.side[kRight].wheel.y.size() - 6], 1e-5));
  // Cone data.
  const Cone c{0.70, -0.45, 0.80, -0.44};
  CHECK(c.radius_at(0.75) == within_rel(0.445, 1e-5));
  CHECK(c.slope_angle() == within_rel(std::atan2(-0.01, 0.10), 1e-5));
  double ny = 0, nr = 0;
  c.meridian_normal(ny, nr);
  CHECK(nr > 0);
  CHECK(ny * 0.10 + nr * (-0.01) == within_abs(0.0, 1e-15));  // normal to the generatrix (m)
  // Constant slope: the tangent turns by about slope_step between kept points, at most max_step apart.
  const Profile fine = test::synthetic_wheel(0.05e-3);
  const Profile cs = resample_constant_slope(fine, 0.01, 1e-3);
  CHECK(cs.y.front() == fine.y.front());
  CHECK(cs.y.back() == fine.y.back());
  CHECK(cs.size() < fine.size() / 4);
  for (std::size_t i = 0; i + 1 < cs.size(); ++i) CHECK(std::hypot(cs.y[i + 1] - cs.y[i], cs.z[i + 1] - cs.z[i]) <= 1e-3 + 1e-12);
  // Dense where curved (flange), sparse where straight (tread).
  auto count_in = [&](double a, double b) {
    return std::count_if(cs.y.begin(), cs.y.end(), [&](double v) { return v >= a && v <= b; });
  };
  CHECK(count_in(-0.060, -0.040) > 2 * count_in(0.000, 0.020));
}

TEST_CASE("one model, several threads, each with its own state: the same results as one thread") {
  const auto model = std::make_shared<const GeometryModel>(
      test::make_model(test::synthetic_wheel(0.5e-3), test::synthetic_rail(0.5e-3), 8));
  std::mt19937_64 rng(21);
  std::vector<Pose> poses;
  for (int k = 0; k < 64; ++k) poses.push_back(test::random_pose(rng, *model->track, test::log_uniform(rng, 1e-6, 1e-3)));
  // Reference, serially.
  std::vector<std::vector<Segment>> ref(poses.size());
  {
    Locator loc(model, std::make_unique<NativeSearch>(NativePlan{true, Scan::walk}));
    for (std::size_t i = 0; i < poses.size(); ++i) {
      const auto& st = loc.locate(poses[i]);
      ref[i] = st.segments(kLeft);
      ref[i].insert(ref[i].end(), st.segments(kRight).begin(), st.segments(kRight).end());
    }
  }
  const int nthreads = 4;
  std::vector<int> mismatches(nthreads, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < nthreads; ++t) {
    threads.emplace_back([&, t] {
      Locator loc(model, std::make_unique<NativeSearch>(NativePlan{true, Scan::walk}));
      for (int rep = 0; rep < 3; ++rep)
        for (std::size_t i = t; i < poses.size(); i += 1) {
          const auto& st = loc.locate(poses[(i + t * 7) % poses.size()]);
          auto segs = st.segments(kLeft);
          segs.insert(segs.end(), st.segments(kRight).begin(), st.segments(kRight).end());
          const auto& r = ref[(i + t * 7) % poses.size()];
          bool same = segs.size() == r.size();
          for (std::size_t k = 0; same && k < segs.size(); ++k) same = segs[k].x_t == r[k].x_t && segs[k].x_l == r[k].x_l;
          if (!same) ++mismatches[t];
        }
    });
  }
  for (auto& th : threads) th.join();
  for (int t = 0; t < nthreads; ++t) CHECK(mismatches[t] == 0);
}

TEST_CASE("errors: windows out of range, a window that cuts a segment, bad poses") {
  const auto m = test::make_model(test::synthetic_wheel(1e-3), test::synthetic_rail(1e-3));
  LocationState st;
  struct BadWindow : PoseSearch {
    void search(SearchContext& ctx, int side) override { ctx.test(side, {0, ctx.line_count(side), 0, 3}); }
  } bad_window;
  CHECK_THROWS_WITH_AS(locate_contact(m, Pose{}, st, bad_window), doctest::Contains("is outside the left side"), Error);
  // Half of the cones only: some line keeps one crossing of its pair.
  struct HalfCones : PoseSearch {
    void search(SearchContext& ctx, int side) override {
      Window w = ctx.all(side);
      w.cone_last = w.cone_last / 2 + 10;
      ctx.test(side, w);
    }
  } half;
  CHECK_THROWS_WITH_AS(locate_contact(m, Pose{0.0, -1e-3, 0, 0.02}, st, half),
                       doctest::Contains("odd number"), Error);
  NativeSearch brute({false, Scan::test});
  CHECK_THROWS_WITH_AS(locate_contact(m, Pose{NAN, 0, 0, 0}, st, brute), doctest::Contains("must be finite"), Error);
  CHECK_THROWS_WITH_AS(locate_contact(m, Pose{0, 0, 0, 1.0}, st, brute), doctest::Contains("0.5 rad"), Error);
  // A model without a coarse level cannot run the coarse pre-search.
  NativeSearch coarse({true, Scan::walk});
  CHECK_THROWS_WITH_AS(locate_contact(m, Pose{}, st, coarse), doctest::Contains("no coarse level"), Error);
}
