// Sweeps of equilibria with continuation along y, on worker threads (equilibrium.hpp).
#include "wrc/core/error.hpp"
#include "wrc/equilibrium/equilibrium.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <thread>

#include <unistd.h>

namespace wrc {
namespace {

// A chain of case indices solved in order, each starting from the previous converged point.
struct Chain {
  int centre = -1;  // the case whose solution starts the chain
  std::vector<int> cases;
};

struct Plan {
  std::vector<int> centres;  // per yaw, the case nearest y = 0 (solved first, cold)
  std::vector<Chain> chains; // per yaw, the cases above and below it, marching outward
};

void check_input(const std::vector<double>& ys, const std::vector<double>& yaws, const SweepOptions& opt) {
  if (ys.empty() || yaws.empty()) fail("sweep: needs at least one y and one yaw");
  if (!(opt.Q > 0) || !std::isfinite(opt.Q)) fail("sweep: Q = {} N must be a positive number", opt.Q);
  for (double y : ys)
    if (!std::isfinite(y)) fail("sweep: y values must be finite");
  for (double a : yaws)
    if (!std::isfinite(a)) fail("sweep: yaw values must be finite");
}

// Cases are yaw-major (case a * ny + i is yaws[a], ys[i]).
Plan make_plan(const std::vector<double>& ys, int yaw_count) {
  const int ny = static_cast<int>(ys.size());
  std::vector<int> order(static_cast<std::size_t>(ny));
  for (int i = 0; i < ny; ++i) order[static_cast<std::size_t>(i)] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return ys[a] < ys[b]; });
  int mid = 0;
  for (int k = 0; k < ny; ++k)
    if (std::abs(ys[order[k]]) < std::abs(ys[order[mid]])) mid = k;
  Plan plan;
  for (int a = 0; a < yaw_count; ++a) {
    const int base = a * ny;
    plan.centres.push_back(base + order[mid]);
    Chain up{base + order[mid], {}}, down{base + order[mid], {}};
    for (int k = mid + 1; k < ny; ++k) up.cases.push_back(base + order[k]);
    for (int k = mid - 1; k >= 0; --k) down.cases.push_back(base + order[k]);
    if (!up.cases.empty()) plan.chains.push_back(std::move(up));
    if (!down.cases.empty()) plan.chains.push_back(std::move(down));
  }
  return plan;
}

// Runs tasks 0..count-1 on the workers, each worker with its own workspace; with one worker, on the calling thread
// (a Lua strategy bound to the caller's state stays on it). An exception that escapes a task is rethrown.
void run_parallel(std::vector<std::unique_ptr<ContactWorkspace>>& workspaces, int count,
                  const std::function<void(ContactWorkspace&, int)>& task) {
  std::atomic<int> next{0};
  auto worker = [&](int id) {
    for (int t; (t = next.fetch_add(1)) < count;) task(*workspaces[static_cast<std::size_t>(id)], t);
  };
  const int threads = static_cast<int>(workspaces.size());
  if (threads == 1) return worker(0);
  std::vector<std::thread> pool;
  std::exception_ptr error;
  std::mutex error_mutex;
  for (int id = 0; id < threads; ++id)
    pool.emplace_back([&, id] {
      try {
        worker(id);
      } catch (...) {  // solve_case catches per case; anything else is a bug worth reporting, not a crash
        std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
      }
    });
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

class SweepRun {
 public:
  SweepRun(const ContactModel& model, const SweepOptions& opt, SweepResult& out)
      : model_(model), opt_(opt), out_(out), total_(static_cast<int>(out.cases.size())) {}

  // Solves one case (recording a failure or an exception in the result); true when it converged.
  bool solve_case(ContactWorkspace& ws, int c, const std::vector<Start>& starts) {
    const SweepCase& sc = out_.cases[static_cast<std::size_t>(c)];
    EquilibriumResult& e = out_.elastic[static_cast<std::size_t>(c)];
    bool ok = false;
    try {
      ContactRequest req;
      req.keep_grids = opt_.keep_grids || opt_.rolling.has_value();  // the tangential step needs the pressure
      e = solve_equilibrium(model_, sc.y, sc.yaw, opt_.Q, ws, opt_.equilibrium, starts, req);
      ok = e.converged;
      if (ok && opt_.rolling) {  // creep forces at the (frictionless) equilibrium's pose
        add_rolling(model_, e.contact, *opt_.rolling, ws);
        if (!opt_.keep_grids) drop_grids(e.contact);
      }
      if (opt_.rigid) out_.rigid[static_cast<std::size_t>(c)] = solve_rigid(model_.geometry(), sc.y, sc.yaw, opt_.Q);
    } catch (const std::exception& ex) {
      out_.errors[static_cast<std::size_t>(c)] = ex.what();
      e.y = sc.y;
      e.yaw = sc.yaw;
      e.Q = opt_.Q;
      e.message = ex.what();
    }
    std::lock_guard<std::mutex> lock(progress_mutex_);
    ++done_;
    if (!ok) ++failed_;
    if (opt_.progress) opt_.progress(done_, total_, failed_);
    return ok;
  }

  // Continuation along a chain: each case starts from the straight line through the last two converged points
  // (from the last one alone after the first step). The workspace starts cold, so that the chain's results do not
  // depend on which worker ran it or what it ran before.
  void run_chain(ContactWorkspace& ws, const Chain& ch) {
    struct Point {
      double y, z, roll;
      std::optional<Eigen::Matrix2d> jacobian;
      bool lifted;
    };
    ws.forget();
    std::vector<Point> path;
    const EquilibriumResult& centre = out_.elastic[static_cast<std::size_t>(ch.centre)];
    if (centre.converged) path.push_back({centre.y, centre.z, centre.roll, centre.jacobian, centre.jacobian_lifted});
    for (int c : ch.cases) {
      std::vector<Start> starts;
      const double yc = out_.cases[static_cast<std::size_t>(c)].y;
      if (path.size() >= 2) {
        const Point& a = path[path.size() - 2];
        const Point& b = path.back();
        const double s = (b.y != a.y) ? (yc - b.y) / (b.y - a.y) : 0.0;
        starts.push_back(Start{b.z + s * (b.z - a.z), b.roll + s * (b.roll - a.roll), b.jacobian, b.lifted});
      }
      if (!path.empty()) starts.push_back(Start{path.back().z, path.back().roll, std::nullopt, false});
      if (solve_case(ws, c, starts)) {
        const EquilibriumResult& e = out_.elastic[static_cast<std::size_t>(c)];
        path.push_back({yc, e.z, e.roll, e.jacobian, e.jacobian_lifted});
      }
    }
  }

 private:
  const ContactModel& model_;
  const SweepOptions& opt_;
  SweepResult& out_;
  std::mutex progress_mutex_;
  int done_ = 0, failed_ = 0, total_ = 0;
};

}  // namespace

SweepResult run_sweep(const ContactModel& model, const std::vector<double>& ys, const std::vector<double>& yaws,
                      const SweepOptions& opt, const std::function<std::unique_ptr<ContactWorkspace>()>& make_workspace) {
  check_input(ys, yaws, opt);
  const auto t0 = std::chrono::steady_clock::now();
  SweepResult out;
  for (double yaw : yaws)
    for (double y : ys) out.cases.push_back({y, yaw});
  out.elastic.resize(out.cases.size());
  out.rigid.resize(out.cases.size());
  out.errors.resize(out.cases.size());
  const Plan plan = make_plan(ys, static_cast<int>(yaws.size()));

  int threads = opt.threads > 0 ? opt.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads = std::max(1, std::min(threads, static_cast<int>(std::max(plan.centres.size(), plan.chains.size()))));
  out.threads = threads;
  std::vector<std::unique_ptr<ContactWorkspace>> workspaces(static_cast<std::size_t>(threads));
  for (auto& w : workspaces) w = make_workspace();

  SweepRun run(model, opt, out);
  run_parallel(workspaces, static_cast<int>(plan.centres.size()), [&](ContactWorkspace& ws, int t) {
    ws.forget();
    run.solve_case(ws, plan.centres[static_cast<std::size_t>(t)], {});
  });
  run_parallel(workspaces, static_cast<int>(plan.chains.size()),
               [&](ContactWorkspace& ws, int t) { run.run_chain(ws, plan.chains[static_cast<std::size_t>(t)]); });
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

SweepOptions read_sweep_options(OptionReader& r) {
  SweepOptions o;
  o.Q = r.need_number("Q");
  o.threads = r.integer("threads", 0, 256).value_or(0);
  o.rigid = r.boolean("rigid").value_or(false);
  o.keep_grids = r.boolean("grids").value_or(false);
  o.equilibrium = read_equilibrium_options(r);
  o.rolling = read_rolling_request(r);
  if (r.boolean("progress").value_or(isatty(STDERR_FILENO) == 1)) {
    const auto t0 = std::chrono::steady_clock::now();
    o.progress = [t0](int done, int total, int failed) {
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::fprintf(stderr, "\rwrc sweep: %d / %d cases, %d failed, %.1f s", done, total, failed, s);
      if (done == total) std::fputc('\n', stderr);
      std::fflush(stderr);
    };
  }
  return o;
}

}  // namespace wrc
