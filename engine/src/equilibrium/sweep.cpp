// Sweeps of equilibria with continuation along y, on worker threads (equilibrium.hpp).
#include "wrc/core/error.hpp"
#include "wrc/wheelset/plausibility.hpp"
#include "wrc/core/parallel.hpp"
#include "wrc/equilibrium/equilibrium.hpp"
#include "wrc/geometry/pose.hpp"

#include "pose_solve.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

namespace wrc {
namespace {

// Every case's position within the pose solvers' limits, before any is solved: a y in mm or a yaw in degrees made
// every case but y = 0 a failed row (Y/Q = 0) rather than an error.
void check_input(const std::vector<double>& ys, const std::vector<double>& yaws) {
  if (ys.empty() || yaws.empty()) fail("sweep: needs at least one y and one yaw");
  for (std::size_t k = 0; k < ys.size(); ++k)
    check_lateral(ys[k], fmt::format("sweep: {}", value_at(k, "y")));
  for (std::size_t k = 0; k < yaws.size(); ++k)
    check_yaw(yaws[k], fmt::format("sweep: {}", value_at(k, "yaw")));
}

// Cuts the cases `report` (in the order they are solved) into pieces of at most `chain`; the first piece starts
// from `lead` (solved first, not reported) when lead >= 0, the others cold at their own first case.
void add_chain(std::vector<SweepChunk>& chunks, const std::vector<int>& report, int lead, int chain) {
  const std::size_t n = report.size(), piece = chain > 0 ? static_cast<std::size_t>(chain) : std::max<std::size_t>(n, 1);
  for (std::size_t k = 0; k < n; k += piece) {
    SweepChunk c;
    if (k == 0 && lead >= 0) c.solve.push_back(lead);
    c.report.assign(report.begin() + static_cast<std::ptrdiff_t>(k),
                    report.begin() + static_cast<std::ptrdiff_t>(std::min(n, k + piece)));
    c.solve.insert(c.solve.end(), c.report.begin(), c.report.end());
    std::sort(c.report.begin(), c.report.end());
    chunks.push_back(std::move(c));
  }
}

// A converged case of a continuation chain.
struct ChainPoint {
  double y, z, roll;
  std::optional<Eigen::Matrix2d> jacobian;
  bool lifted;
};

// The start of the chain's next case at y: the polynomial through its last points of distinct y -- a parabola
// through three, a line through two -- evaluated at y (Lagrange), with the last point's Jacobian; none before two.
std::optional<Start> predicted_start(const std::vector<ChainPoint>& path, double y) {
  std::vector<const ChainPoint*> points;
  for (auto it = path.rbegin(); it != path.rend() && points.size() < 3; ++it)
    if (std::none_of(points.begin(), points.end(), [&](const ChainPoint* p) { return p->y == it->y; })) points.push_back(&*it);
  if (points.size() < 2) return std::nullopt;
  Start st{0.0, 0.0, path.back().jacobian, path.back().lifted};
  for (const ChainPoint* p : points) {
    double w = 1;
    for (const ChainPoint* q : points)
      if (q != p) w *= (y - q->y) / (p->y - q->y);
    st.z += w * p->z;
    st.roll += w * p->roll;
  }
  return st;
}

class SweepRun {
 public:
  SweepRun(const ContactModel& model, const SweepPlan& plan, const SweepOptions& opt, SweepResult& out)
      : model_(model), plan_(plan), opt_(opt), out_(out), progress_(opt.progress, static_cast<int>(out.index.size())) {
    slot_.assign(plan.cases.size(), -1);
    for (std::size_t k = 0; k < out.index.size(); ++k) slot_[static_cast<std::size_t>(out.index[k])] = static_cast<int>(k);
  }

  // Continuation along a chunk: its first case from a cold start, each next one from the parabola through the last
  // three converged points (predicted_start; the last point alone if that fails). z(y) and roll(y) curve enough
  // that a line's start is ~2e-3 Q off at 0.1 mm steps, a parabola's ~1e-4 Q, from which one Newton step mostly
  // converges. The workspace is emptied before and after the first case, so that the chunk's results do not depend
  // on which worker ran it or what it ran before.
  void run_chunk(ContactWorkspace& ws, const SweepChunk& chunk) {
    std::vector<ChainPoint> path;
    const bool has_lead = chunk.solve.size() > chunk.report.size();
    EquilibriumResult lead;  // the first case when the chunk does not report it (the centre of a series)
    for (std::size_t k = 0; k < chunk.solve.size(); ++k) {
      if (stop_requested(opt_.stop)) {  // stopped: the rest of the chunk is not begun
        cut_ = true;
        return;
      }
      const int c = chunk.solve[k];
      const double yc = plan_.cases[static_cast<std::size_t>(c)].y;
      std::vector<Start> starts;
      if (const std::optional<Start>& given = opt_.starts.empty() ? std::nullopt : opt_.starts[static_cast<std::size_t>(c)]) {
        Start g = *given;
        if (!path.empty()) g.jacobian = path.back().jacobian, g.jacobian_lifted = path.back().lifted;
        starts.push_back(g);
      }
      if (auto st = predicted_start(path, yc)) starts.push_back(*st);
      if (!path.empty()) starts.push_back(Start{path.back().z, path.back().roll, std::nullopt, false});
      if (k <= 1) ws.forget();
      const bool reported = !(k == 0 && has_lead);
      const int slot = reported ? slot_[static_cast<std::size_t>(c)] : -1;
      EquilibriumResult& e = reported ? out_.elastic[static_cast<std::size_t>(slot)] : lead;
      if (solve_case(ws, c, slot, e, starts, reported)) path.push_back({yc, e.z, e.roll, e.jacobian, e.jacobian_lifted});
      if (reported) ++solved_;
    }
  }

  // Whether SweepOptions::stop left cases unsolved, and how many were solved.
  bool cut() const { return cut_; }
  int solved() const { return solved_; }

 private:
  // Solves one case into `e` (recording a failure or an exception); true when it converged. A reported case gets
  // its rigid reference and counts for the progress.
  bool solve_case(ContactWorkspace& ws, int c, int slot, EquilibriumResult& e, const std::vector<Start>& starts,
                  bool reported) {
    const SweepCase& sc = plan_.cases[static_cast<std::size_t>(c)];
    bool ok = false;
    try {
      ContactRequest req;
      const bool rolling = opt_.rolling.has_value() && reported;
      req.keep_grids = (opt_.keep_grids || rolling) && reported;  // the tangential step needs the pressure
      const ContactStart* given = opt_.contact_starts.empty() ? nullptr : opt_.contact_starts[static_cast<std::size_t>(c)].get();
      if (given) given->adopt_normal(ws);
      e = solve_equilibrium(model_, {sc.y, sc.yaw, opt_.Q}, ws, opt_.equilibrium, starts, req);
      ok = e.converged;
      if (ok && rolling) {  // creep forces at the (frictionless) equilibrium's pose
        if (given) given->adopt_tangential(ws);
        add_rolling(model_, e.contact, *opt_.rolling, ws);
        if (!opt_.keep_grids) drop_grids(e.contact, opt_.keep_rows);  // rows: a wear loop's input, a hundredth of the numbers
      }
      if (ok && reported && opt_.keep_starts)
        out_.contact_starts[static_cast<std::size_t>(slot)] = std::make_shared<const ContactStart>(ContactStart{ws.previous, ws.tangential, ws.spin});
      if (opt_.rigid && reported)
        out_.rigid[static_cast<std::size_t>(slot)] = solve_rigid(model_.geometry(), sc.y, sc.yaw, opt_.Q);
    } catch (const std::exception& ex) {
      if (reported) out_.errors[static_cast<std::size_t>(slot)] = ex.what();
      e.y = sc.y;
      e.yaw = sc.yaw;
      e.Q = opt_.Q;
      e.message = ex.what();
      e.converged = ok = false;  // also when the equilibrium converged and its rolling contact failed
    }
    if (reported) progress_.add(!ok);
    return ok;
  }

  const ContactModel& model_;
  const SweepPlan& plan_;
  const SweepOptions& opt_;
  SweepResult& out_;
  std::vector<int> slot_;  // per case of the plan, its entry in out_ (-1: not in this run)
  ProgressCount progress_;
  std::atomic<bool> cut_{false};
  std::atomic<int> solved_{0};
};

}  // namespace

SweepPlan plan_sweep(const std::vector<double>& ys, const std::vector<double>& yaws, int chain) {
  check_input(ys, yaws);
  if (chain < 0) fail("sweep: chain = {} must be >= 0 (0: whole continuation chains)", chain);
  const int ny = static_cast<int>(ys.size());
  std::vector<int> order(static_cast<std::size_t>(ny));
  for (int i = 0; i < ny; ++i) order[static_cast<std::size_t>(i)] = i;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return ys[a] < ys[b]; });
  int mid = 0;
  for (int k = 0; k < ny; ++k)
    if (std::abs(ys[order[k]]) < std::abs(ys[order[mid]])) mid = k;
  SweepPlan plan;
  for (double yaw : yaws)
    for (double y : ys) plan.cases.push_back({y, yaw});
  for (int a = 0; a < static_cast<int>(yaws.size()); ++a) {
    const int base = a * ny;
    std::vector<int> up, down;
    for (int k = mid; k < ny; ++k) up.push_back(base + order[k]);
    for (int k = mid - 1; k >= 0; --k) down.push_back(base + order[k]);
    add_chain(plan.chunks, down, base + order[mid], chain);
    add_chain(plan.chunks, up, -1, chain);
  }
  std::stable_sort(plan.chunks.begin(), plan.chunks.end(),
                   [](const SweepChunk& a, const SweepChunk& b) { return a.report.front() < b.report.front(); });
  return plan;
}

SweepResult run_sweep(const ContactModel& model, const SweepPlan& plan, const std::vector<int>& chunks,
                      const SweepOptions& opt, const std::function<std::unique_ptr<ContactWorkspace>()>& make_workspace) {
  if (!(opt.Q > 0) || !std::isfinite(opt.Q)) fail("sweep: Q = {} N must be a positive number", opt.Q);
  if (model.options().check_magnitudes) check_plausible("sweep", "Q", opt.Q, kWheelsetLoad);
  opt.equilibrium.validate("sweep");  // once here rather than as every case's error
  if (!opt.starts.empty() && opt.starts.size() != plan.cases.size())
    fail("sweep: starts has {} entries; the plan has {} cases (one per y and yaw)", opt.starts.size(), plan.cases.size());
  if (!opt.contact_starts.empty() && opt.contact_starts.size() != plan.cases.size())
    fail("sweep: starts has {} contact entries; the plan has {} cases (one per y and yaw)", opt.contact_starts.size(),
         plan.cases.size());
  for (std::size_t k = 0; k < opt.starts.size(); ++k)
    if (opt.starts[k] && (!std::isfinite(opt.starts[k]->z) || !std::isfinite(opt.starts[k]->roll)))
      fail("sweep: {} and of starts.roll: z = {} m, roll = {} rad must be finite", value_at(k, "starts.z"),
           opt.starts[k]->z, opt.starts[k]->roll);
  const auto t0 = std::chrono::steady_clock::now();
  SweepResult out;
  std::vector<bool> taken(plan.chunks.size(), false);
  for (int k : chunks) {
    if (k < 0 || k >= static_cast<int>(plan.chunks.size()))
      fail("sweep: chunk {} does not exist (the plan has {} chunks)", k + 1, plan.chunks.size());
    if (taken[static_cast<std::size_t>(k)]) fail("sweep: chunk {} is listed twice", k + 1);
    taken[static_cast<std::size_t>(k)] = true;
    const auto& r = plan.chunks[static_cast<std::size_t>(k)].report;
    out.index.insert(out.index.end(), r.begin(), r.end());
  }
  std::sort(out.index.begin(), out.index.end());
  for (int c : out.index) out.cases.push_back(plan.cases[static_cast<std::size_t>(c)]);
  out.elastic.resize(out.index.size());
  out.rigid.resize(out.index.size());
  out.errors.resize(out.index.size());
  if (opt.keep_starts) out.contact_starts.resize(out.index.size());

  // One chunk per task: a chunk's cases follow each other by continuation, and chunks do not depend on each other.
  const int count = static_cast<int>(chunks.size());
  const ThreadCount tc =
      thread_count(opt.threads, opt.single_thread.empty() ? count : 1,
                   !opt.single_thread.empty() ? opt.single_thread
                   : fmt::format("the sweep has {} chunk{} (continuation chains: per yaw, outward from the centre on "
                                 "each side), one per thread", count, count == 1 ? "" : "s"));
  out.threads = tc.threads;
  out.threads_note = tc.note;
  if (!tc.note.empty() && opt.notice) opt.notice(tc.note);
  std::vector<std::unique_ptr<ContactWorkspace>> workspaces(static_cast<std::size_t>(tc.threads));
  for (auto& w : workspaces) w = make_workspace();

  SweepRun run(model, plan, opt, out);
  parallel_for(count, tc.threads, [&](int worker, int t) {
    run.run_chunk(*workspaces[static_cast<std::size_t>(worker)],
                  plan.chunks[static_cast<std::size_t>(chunks[static_cast<std::size_t>(t)])]);
  });
  if (run.cut())
    fail("sweep: stopped by its caller after {} of {} cases (the others were not begun)", run.solved(),
         out.index.size());
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

SweepResult run_sweep(const ContactModel& model, const std::vector<double>& ys, const std::vector<double>& yaws,
                      const SweepOptions& opt, const std::function<std::unique_ptr<ContactWorkspace>()>& make_workspace) {
  const SweepPlan plan = plan_sweep(ys, yaws, opt.chain);
  std::vector<int> all(plan.chunks.size());
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int>(k);
  return run_sweep(model, plan, all, opt, make_workspace);
}

SweepOptions read_sweep_options(OptionReader& r) {
  SweepOptions o;
  o.Q = r.need_number("Q", {"N", "vertical load at the wheelset centre"});
  o.threads = read_threads(r, o.threads);
  o.rigid = r.boolean("rigid", {"-", "also solve the rigid reference of each case"}, o.rigid);
  o.keep_grids = r.boolean("grids", {"-", "keep the pressure and h grids of every case"}, o.keep_grids);
  o.keep_rows = r.boolean("rows", {"-", "without the grids: keep each area's per-row results (wear_passage)"},
                          o.keep_rows);
  o.chain = r.integer("chain", 0, 100000000, {"-", "reported cases per chunk at most (0: whole chains)"}, o.chain);
  o.equilibrium = read_newton_options(r);
  o.rolling = read_rolling_request(r);
  return o;
}

}  // namespace wrc
