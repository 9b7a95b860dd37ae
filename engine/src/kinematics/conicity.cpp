// Equivalent conicity of a Δr function (conicity.hpp): the integral method (the kinematic wheelset motion),
// harmonic linearisation, linear regression and the simple quotient.
#include "wrc/kinematics/conicity.hpp"

#include "wrc/core/error.hpp"
#include "wrc/core/roots.hpp"
#include "wrc/geometry/pose.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string_view>

namespace wrc {
namespace {

constexpr const char* kCtx = "wrc.conicity";

// An amplitude of the lateral motion: positive, at most 50 mm (a flange's reach; beyond, the flange limits it).
// `context` names the call in the message (the reader's, when the options are read; kCtx for a direct call).
void check_amplitude(double a, std::string_view context) {
  if (!(a > 0) || !std::isfinite(a) || a > 0.05)
    fail("{}: the amplitude yhat = {} m must be a positive number of metres (up to 0.05)", context, a);
}

// 8-point Gauss-Legendre nodes and weights on [-1, 1].
constexpr std::array<double, 8> kNodes{-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                                        -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                                        0.7966664774136267,  0.9602898564975363};
constexpr std::array<double, 8> kWeights{0.1012285362903763, 0.2223810344533745, 0.3137066458778873,
                                         0.3626837833783620, 0.3626837833783620, 0.3137066458778873,
                                         0.2223810344533745, 0.1012285362903763};

// Integral of f over [a, b] split at `breaks` (inside), 8-point Gauss-Legendre per panel.
template <class F>
double gauss(F&& f, double a, double b, std::vector<double> breaks) {
  breaks.push_back(a);
  breaks.push_back(b);
  std::sort(breaks.begin(), breaks.end());
  double sum = 0;
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double lo = std::max(a, breaks[k]), hi = std::min(b, breaks[k + 1]);
    if (!(hi > lo)) continue;
    const double m = 0.5 * (lo + hi), r = 0.5 * (hi - lo);
    for (std::size_t i = 0; i < kNodes.size(); ++i) sum += kWeights[i] * r * f(m + r * kNodes[i]);
  }
  return sum;
}

// The piecewise-linear Δr and its integral G (G(y0) = 0).
class Table {
 public:
  explicit Table(const DeltaRFunction& d) : y_(d.y), d_(d.dr), flange_(d.flange) {
    C_.assign(y_.size(), 0.0);
    for (std::size_t i = 1; i < y_.size(); ++i) C_[i] = C_[i - 1] + 0.5 * (d_[i] + d_[i - 1]) * (y_[i] - y_[i - 1]);
    find_centre();
  }
  double centre() const { return y0_; }
  // The zone around the centre where Δr is exactly zero (a worn pair's flat zone; empty: flat_lo == flat_hi).
  double flat_lo() const { return flat_lo_; }
  double flat_hi() const { return flat_hi_; }
  double front() const { return y_.front(); }
  double back() const { return y_.back(); }
  double dr(double x) const {
    const std::size_t i = seg(x);
    return d_[i] + (d_[i + 1] - d_[i]) * (x - y_[i]) / (y_[i + 1] - y_[i]);
  }
  double G(double x) const { return C(x) - G0_; }
  // The integral of Δr over [a, b] piece by piece: no cancellation of two large G values near a turning point.
  double integral(double a, double b) const {
    double sum = 0, p = a;
    for (double k : knots(a, b)) {
      sum += piece(p, k);
      p = k;
    }
    return sum + piece(p, b);
  }
  // The integral of Δr from a over a signed offset delta, exact for offsets below the rounding of a + delta.
  double integral_by(double a, double delta) const {
    const double b = a + delta;
    if (!knots(std::min(a, b), std::max(a, b)).empty()) return delta > 0 ? integral(a, b) : -integral(b, a);
    const std::size_t i = seg(delta > 0 ? a : b);
    const double slope = (d_[i + 1] - d_[i]) / (y_[i + 1] - y_[i]);
    return delta * (dr(a) + 0.5 * slope * delta);
  }
  // Knots strictly inside ]a, b[ (panel breaks: Δr has kinks there).
  std::vector<double> knots(double a, double b) const {
    if (!(b > a)) return {};
    return {std::upper_bound(y_.begin(), y_.end(), a), std::lower_bound(y_.begin(), y_.end(), b)};
  }
  // The integral of Δr from the knot k to x within one linear piece (exact: the trapezoid of a straight line).
  double piece(double k, double x) const { return 0.5 * (dr(k) + dr(x)) * (x - k); }
  // Where G may peak inside ]a, b[: the knots and the points where Δr falls through zero.
  std::vector<double> peaks(double a, double b) const {
    std::vector<double> p = knots(a, b);
    for (std::size_t i = 0; i + 1 < y_.size(); ++i)
      if (d_[i] >= 0 && d_[i + 1] < 0) {
        const double z = y_[i] + d_[i] / (d_[i] - d_[i + 1]) * (y_[i + 1] - y_[i]);
        if (z > a && z < b) p.push_back(z);
      }
    return p;
  }
  // Fails when a table point inside [a, b] is marked as flange contact.
  void check_flange(double a, double b, double yhat) const {
    for (std::size_t i = 0; i < flange_.size() && i < y_.size(); ++i)
      if (flange_[i] && y_[i] >= a && y_[i] <= b)
        fail("{}: flange contact inside the motion of amplitude yhat = {:.3f} mm (y = {:.3f} .. {:.3f} mm): the Δr table "
             "marks flange contact at y = {:.3f} mm; EN 15302's equivalent conicity is not defined where the flange "
             "limits the motion (choose a smaller amplitude)",
             kCtx, yhat * 1e3, a * 1e3, b * 1e3, y_[i] * 1e3);
  }
  void check_inside(double a, double b, double yhat) const {
    if (a < y_.front() - 1e-15 || b > y_.back() + 1e-15)
      fail("{}: the amplitude yhat = {:.4g} mm needs Δr over y = {:.4f} .. {:.4f} mm, beyond the table ({:.4f} .. {:.4f} "
           "mm): extend the table or choose a smaller amplitude",
           kCtx, yhat * 1e3, a * 1e3, b * 1e3, y_.front() * 1e3, y_.back() * 1e3);
  }

 private:
  std::size_t seg(double x) const {
    const auto it = std::upper_bound(y_.begin(), y_.end(), x);
    const auto i = static_cast<std::ptrdiff_t>(it - y_.begin()) - 1;
    return static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(i, 0, static_cast<std::ptrdiff_t>(y_.size()) - 2));
  }
  double C(double x) const {
    const std::size_t i = seg(x);
    const double t = x - y_[i], s = (d_[i + 1] - d_[i]) / (y_[i + 1] - y_[i]);
    return C_[i] + d_[i] * t + 0.5 * s * t * t;
  }
  // The rising zero of Δr nearest y = 0 (the motion's centre). Where Δr rises through a run of knots at exactly zero
  // (a flat zone), the centre is the middle of that zone.
  void find_centre() {
    bool found = false, falling = false;
    const std::size_t n = y_.size();
    auto candidate = [&](double z, double lo, double hi) {
      if (found && std::abs(z) >= std::abs(y0_)) return;
      y0_ = z, flat_lo_ = lo, flat_hi_ = hi;
      found = true;
    };
    for (std::size_t i = 0; i + 1 < n; ++i) {
      const double a = d_[i], b = d_[i + 1];
      if (a < 0 && b > 0) {
        const double z = y_[i] + (0 - a) / (b - a) * (y_[i + 1] - y_[i]);
        candidate(z, z, z);
      } else if ((a < 0 || i == 0) && a <= 0 && b == 0) {  // into a run of zeros (from the table's start when a = 0)
        const std::size_t first = a == 0 ? i : i + 1;
        std::size_t last = i + 1;
        while (last + 1 < n && d_[last + 1] == 0) ++last;
        if (last + 1 == n ? a < 0 : d_[last + 1] > 0) candidate(0.5 * (y_[first] + y_[last]), y_[first], y_[last]);
        else falling = falling || a == 0;  // from zero at the start down: falls
        i = last - 1;
      } else if (i == 0 && a == 0 && b > 0) {
        candidate(y_[0], y_[0], y_[0]);
      } else if ((a >= 0 && b < 0) || (a > 0 && b <= 0)) {
        falling = true;
      }
    }
    if (!found && falling)
      fail("{}: Δr falls through zero and never rises through it: the wheelset is not self-centring with this table "
           "(Δr must be r_left - r_right, rising with y toward the left rail; check the sign)", kCtx);
    if (!found)
      fail("{}: Δr does not change sign over the table (y = {:.3f} .. {:.3f} mm, Δr = {:.4f} .. {:.4f} mm): no centre "
           "of the motion; a Δr function of a wheelset on its track rises through zero",
           kCtx, y_.front() * 1e3, y_.back() * 1e3, *std::min_element(d_.begin(), d_.end()) * 1e3,
           *std::max_element(d_.begin(), d_.end()) * 1e3);
    G0_ = C(y0_);
  }

  const std::vector<double>& y_;
  const std::vector<double>& d_;
  const std::vector<bool>& flange_;
  std::vector<double> C_;  // integral of Δr from y_[0] at the knots
  double y0_ = 0, G0_ = 0;
  double flat_lo_ = 0, flat_hi_ = 0;
};

// Integral method: the turning points y1 < y0 < y2 of the motion with y2 - y1 = 2 yhat, and I = the integral of
// dy / sqrt(G(turn) - G(y)) over [y1, y2], each half substituted y = turn -+ L u^2 so that the 1/sqrt of the turning
// points disappears. tan(gamma_e) = pi^2 / I^2.
void integral_method(const Table& t, double yhat, double& y1, double& y2, double& tan_gamma) {
  const double y0 = t.centre(), L = 2 * yhat;
  const double lo = std::max(y0 - L, t.front()), hi = std::min(y0, t.back() - L);
  auto h = [&](double a) { return t.G(a) - t.G(a + L); };
  auto leaves = [&](const char* side) {
    fail("{}: the motion of amplitude yhat = {:.4g} mm about y0 = {:.4f} mm leaves the Δr table on its {} side (the "
         "table covers y = {:.4f} .. {:.4f} mm): extend the table or choose a smaller amplitude",
         kCtx, yhat * 1e3, y0 * 1e3, side, t.front() * 1e3, t.back() * 1e3);
  };
  auto not_one = [&] {
    fail("{}: the motion of amplitude yhat = {:.4g} mm is not one oscillation about y0 = {:.4f} mm: Δr has other zeros "
         "within it (the wheelset would rest there)", kCtx, yhat * 1e3, y0 * 1e3);
  };
  if (lo > hi) leaves(y0 - L < t.front() ? "-y" : "+y");
  const double hlo = h(lo), hhi = h(hi);
  if (hlo < 0) lo == t.front() ? leaves("-y") : not_one();
  if (hhi > 0) hi == t.back() - L ? leaves("+y") : not_one();
  bool ok = false;
  const double scale = std::max({std::abs(hlo), std::abs(hhi), 1e-300});
  y1 = hlo == 0 ? lo : (hhi == 0 ? hi : bracketed_root(h, lo, hi, hlo, hhi, 1e-14 * scale, 300, ok));
  y2 = y1 + L;
  const double g1 = t.G(y1), g2 = t.G(y2);
  if (!(t.dr(y1) < 0 && t.dr(y2) > 0))
    fail("{}: the motion of amplitude yhat = {:.4g} mm stalls at a turning point where Δr = 0 (y = {:.4f} .. {:.4f} mm)",
         kCtx, yhat * 1e3, y1 * 1e3, y2 * 1e3);
  const double level = std::max(g1, g2), margin = 1e-9 * L;  // knots on a turning point are turning points
  for (double k : t.peaks(y1 + margin, y2 - margin))
    if (t.G(k) >= level) not_one();
  // y = turn + len u^2, u in [0, 1] (len signed); G(turn) - G(y) = -integral of Δr from the turning point, one panel
  // per piece of the table, the integral up to the panel's first knot carried from panel to panel (summed piece by
  // piece as Table::integral does, so linear in the table's length).
  auto half = [&](double turn, double len) {
    std::vector<double> edges{turn};
    std::vector<double> k = t.knots(std::min(turn, turn + len), std::max(turn, turn + len));
    if (len < 0) std::reverse(k.begin(), k.end());  // from the turning point toward the centre
    for (double v : k)
      if (std::sqrt((v - turn) / len) > 1e-6) edges.push_back(v);  // a knot on the turning point is no kink
    edges.push_back(turn + len);
    double sum = 0, carried = 0;  // carried: the integral of Δr from the turning point to edges[j]
    for (std::size_t j = 0; j + 1 < edges.size(); ++j) {
      const double from = edges[j], ua = j == 0 ? 0.0 : std::sqrt((from - turn) / len);
      const double ub = j + 2 == edges.size() ? 1.0 : std::sqrt((edges[j + 1] - turn) / len);
      sum += gauss([&](double u) {
        const double y = turn + len * u * u;
        const double dG = -(j == 0 ? t.integral_by(turn, len * u * u) : carried + t.piece(from, y));
        return 2 * std::abs(len) * u / std::sqrt(std::max(dG, 1e-300));
      }, ua, ub, {});
      carried = j == 0 ? t.integral_by(turn, edges[1] - turn) : carried + t.piece(from, edges[j + 1]);
    }
    return sum;
  };
  const double I = half(y1, y0 - y1) + half(y2, y0 - y2);
  tan_gamma = std::numbers::pi * std::numbers::pi / (I * I);
}

double harmonic_method(const Table& t, double yhat) {
  const double y0 = t.centre();
  std::vector<double> breaks;
  for (double k : t.knots(y0 - yhat, y0 + yhat)) breaks.push_back(std::asin((k - y0) / yhat));
  const double pi = std::numbers::pi;
  // The integral over [0, 2 pi] is twice the one over [-pi/2, pi/2] (phi -> pi - phi keeps y and sin phi).
  const double s = gauss([&](double phi) { return t.dr(y0 + yhat * std::sin(phi)) * std::sin(phi); }, -pi / 2, pi / 2,
                         breaks);
  return 2 * s / (2 * pi * yhat);
}

double regression_method(const Table& t, double yhat) {
  const double y0 = t.centre();
  // Least squares over the interval: slope = integral (y - y0) Δr dy / integral (y - y0)^2 dy (exact per panel).
  const double m = gauss([&](double yy) { return (yy - y0) * t.dr(yy); }, y0 - yhat, y0 + yhat, t.knots(y0 - yhat, y0 + yhat));
  const double slope = m / (2 * yhat * yhat * yhat / 3);
  return slope / 2;
}

// The Δr table's sizes and values; `context` as for check_amplitude.
void check_input(const DeltaRFunction& d, std::string_view context) {
  const std::size_t n = d.y.size();
  if (d.dr.size() != n) fail("{}: y has {} values but dr has {}", context, n, d.dr.size());
  if (n < 3) fail("{}: a Δr table needs at least 3 points, got {}", context, n);
  if (!d.flange.empty() && d.flange.size() != n) fail("{}: flange has {} values for {} points", context, d.flange.size(), n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(d.y[i]) || !std::isfinite(d.dr[i]))
      fail("{}: the {} point is not a finite number (y = {}, dr = {})", context, ordinal(i + 1), d.y[i], d.dr[i]);
    check_lateral(d.y[i], fmt::format("{}: {}", context, value_at(i, "y")));
    if (std::abs(d.dr[i]) > 0.05)
      fail("{}: {} (= {} m): Δr is a rolling radius difference in metres, a few mm at most (mm given?)", context,
           value_at(i, "dr"),
           d.dr[i]);
    if (i > 0 && !(d.y[i] > d.y[i - 1]))
      fail("{}: y must increase strictly: {} (= {} m) after {} m", context, value_at(i, "y"), d.y[i], d.y[i - 1]);
  }
}

}  // namespace

const char* to_string(ConicityMethod m) {
  switch (m) {
    case ConicityMethod::integral: return "integral";
    case ConicityMethod::harmonic: return "harmonic";
    case ConicityMethod::regression: return "regression";
    case ConicityMethod::simple: return "simple";
  }
  return "?";
}

ConicityResult equivalent_conicity(const DeltaRFunction& d, const ConicityOptions& o) {
  check_input(d, kCtx);
  if (o.yhat.empty()) fail("{}: 'yhat' needs at least one amplitude (m)", kCtx);
  if (!(o.r0 > 0) || !(o.contact_distance > 0) || !std::isfinite(o.r0) || !std::isfinite(o.contact_distance))
    fail("{}: r0 = {} m and contact_distance = {} m must be positive", kCtx, o.r0, o.contact_distance);
  const Table t(d);
  ConicityResult r;
  r.method = o.method;
  r.centre = t.centre();
  r.flat_zone = {t.flat_lo(), t.flat_hi()};
  const double flat_half = 0.5 * (t.flat_hi() - t.flat_lo());
  if (flat_half > 0)
    r.note = fmt::format("Δr = 0 over y = {:.4f} .. {:.4f} mm around the centre: no restoring Δr within it, so tan γe = 0 "
                         "(an infinite wavelength; EN 15302) for amplitudes up to {:.4f} mm",
                         t.flat_lo() * 1e3, t.flat_hi() * 1e3, flat_half * 1e3);
  for (double a : o.yhat) {
    check_amplitude(a, kCtx);
    double lo = r.centre - a, hi = r.centre + a, tg = 0;
    if (a <= flat_half * (1 + 1e-12)) {
      // The wheelset moves freely inside the flat zone: Δr = 0 over the whole motion, every method gives 0.
    } else if (o.method == ConicityMethod::integral) {
      integral_method(t, a, lo, hi, tg);
    } else {
      t.check_inside(lo, hi, a);
      if (o.method == ConicityMethod::harmonic) tg = harmonic_method(t, a);
      else if (o.method == ConicityMethod::regression) tg = regression_method(t, a);
      else tg = (t.dr(hi) - t.dr(lo)) / (4 * a);
    }
    t.check_flange(lo, hi, a);
    r.yhat.push_back(a);
    r.tan_gamma.push_back(tg);
    r.y_min.push_back(lo);
    r.y_max.push_back(hi);
    const double e = 0.5 * o.contact_distance;
    r.wavelength.push_back(tg > 0 ? 2 * std::numbers::pi * std::sqrt(e * o.r0 / tg)
                                  : a <= flat_half * (1 + 1e-12) ? INFINITY : 0.0);
  }
  return r;
}

ConicityOptions read_conicity_options(OptionReader& r, ConicityOptions o) {
  const auto yhat = r.numbers("yhat", {"m", "amplitude(s) of the lateral motion (required)"});
  if (!yhat && !r.documenting()) fail("{}: 'yhat' is required: an amplitude or an array of amplitudes (m)", r.context());
  if (yhat) o.yhat = *yhat;
  // Checked as they are read, so that the message names the call and a front end reports a bad argument; and before
  // ws:conicity builds a table as wide as the largest.
  if (yhat && yhat->empty()) fail("{}: 'yhat' needs at least one amplitude (m)", r.context());
  for (double a : o.yhat) check_amplitude(a, r.context());
  const std::string m = r.choice("method", {"integral", "harmonic", "regression", "simple"},
                                 {"-", "how tan(gamma_e) is made of the Δr table (EN 15302)"}, to_string(o.method));
  o.method = m == "integral"   ? ConicityMethod::integral
             : m == "harmonic" ? ConicityMethod::harmonic
             : m == "regression" ? ConicityMethod::regression
                                 : ConicityMethod::simple;
  o.r0 = r.number("r0", {"m", "nominal rolling radius (the wavelength only; 0: the wheelset's)"}, o.r0);
  o.contact_distance = r.number(
      "contact_distance", {"m", "distance 2e of the contact points (the wavelength only; 0: the wheelset's)"},
      o.contact_distance);
  return o;
}

DeltaRFunction read_delta_r(OptionReader& r) {
  DeltaRFunction d;
  auto y = r.numbers("y", {"m", "lateral positions of the Δr table (required)"}, false);
  auto dr = r.numbers("dr", {"m", "rolling radius difference left - right at each y (required)"}, false);
  if (r.documenting()) {
    r.value("flange", "booleans", {"-", "flange contact at each y (optional)"});
    return d;
  }
  if (!y || !dr) fail("{}: the Δr table needs arrays 'y' and 'dr' (m)", r.context());
  d.y = std::move(*y);
  d.dr = std::move(*dr);
  if (const OptionValue* f = r.value("flange")) {
    if (f->type != OptionValue::Type::array)
      fail("{}: 'flange' must be booleans (or 0/1), one per value of 'y', got {}", r.context(), r.type_name(*f));
    for (std::size_t i = 0; i < f->array.size(); ++i) {
      const OptionValue& v = f->array[i];
      if (v.type == OptionValue::Type::boolean) d.flange.push_back(v.boolean);
      else if (v.type == OptionValue::Type::number && (v.number == 0 || v.number == 1)) d.flange.push_back(v.number == 1);
      else fail("{}: {} must be a boolean (or 0/1), got {}", r.context(), value_at(i, "'flange'"), r.type_name(v));
    }
  }
  check_input(d, r.context());  // as it is read: the message names the call, a front end reports a bad argument
  return d;
}

void describe(const ConicityResult& r, FieldSink& out) {
  out.string("method", to_string(r.method), {"", "integral, harmonic, regression or simple (EN 15302)"});
  out.number("centre", r.centre, {"m", "y0, where the rolling radius difference rises through zero"});
  out.numbers("yhat", r.yhat.data(), r.yhat.size(), {"m", "the amplitudes"});
  out.numbers("tan_gamma", r.tan_gamma.data(), r.tan_gamma.size(), {"-", "equivalent conicity tan(gamma_e), one per amplitude"});
  out.numbers("y_min", r.y_min.data(), r.y_min.size(), {"m", "lowest y the method used (integral: the turning point)"});
  out.numbers("y_max", r.y_max.data(), r.y_max.size(), {"m", "highest y the method used (integral: the turning point)"});
  out.numbers("wavelength", r.wavelength.data(), r.wavelength.size(),
              {"m", "Klingel wavelength of tan_gamma with r0 and contact_distance"});
  if (!r.note.empty()) {
    out.string("note", r.note, {"", "why some amplitudes have tan_gamma = 0 (a flat zone of zero rolling radius difference)"});
    out.numbers("flat_zone", r.flat_zone.data(), r.flat_zone.size(),
                {"m", "the band of y around the centre where the rolling radius difference is exactly zero"});
  }
}

}  // namespace wrc
