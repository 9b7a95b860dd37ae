// Sweeps of equilibria with continuation along y, on worker threads (equilibrium.hpp).
#include "wrc/core/error.hpp"
#include "wrc/equilibrium/equilibrium.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <thread>

namespace wrc {
namespace {

// A chain of case indices solved in order, each starting from the previous converged point.
struct Chain {
  int centre = -1;              // the case whose solution starts the chain (-1: start cold)
  std::vector<int> cases;
};

}  // namespace

SweepResult run_sweep(const ContactModel& model, const std::vector<double>& ys, const std::vector<double>& yaws,
                      const SweepOptions& opt, const std::function<std::unique_ptr<ContactWorkspace>()>& make_workspace) {
  if (ys.empty() || yaws.empty()) fail("sweep: needs at least one y and one yaw");
  if (!(opt.Q > 0) || !std::isfinite(opt.Q)) fail("sweep: Q = {} N must be a positive number", opt.Q);
  for (double y : ys)
    if (!std::isfinite(y)) fail("sweep: y values must be finite");
  for (double a : yaws)
    if (!std::isfinite(a)) fail("sweep: yaw values must be finite");
  const auto t0 = std::chrono::steady_clock::now();
  SweepResult out;
  const int ny = static_cast<int>(ys.size());
  for (double yaw : yaws)
    for (double y : ys) out.cases.push_back({y, yaw});
  const int total = static_cast<int>(out.cases.size());
  out.elastic.resize(static_cast<std::size_t>(total));
  out.rigid.resize(static_cast<std::size_t>(total));
  out.errors.resize(static_cast<std::size_t>(total));

  // Per yaw: the case nearest y = 0 first, then two chains marching outward in y.
  std::vector<int> order(static_cast<std::size_t>(ny));
  for (int i = 0; i < ny; ++i) order[static_cast<std::size_t>(i)] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return ys[a] < ys[b]; });
  int mid = 0;
  for (int k = 0; k < ny; ++k)
    if (std::abs(ys[order[k]]) < std::abs(ys[order[mid]])) mid = k;
  std::vector<int> centres;
  std::vector<Chain> chains;
  for (int a = 0; a < static_cast<int>(yaws.size()); ++a) {
    const int base = a * ny;
    centres.push_back(base + order[mid]);
    Chain up{base + order[mid], {}}, down{base + order[mid], {}};
    for (int k = mid + 1; k < ny; ++k) up.cases.push_back(base + order[k]);
    for (int k = mid - 1; k >= 0; --k) down.cases.push_back(base + order[k]);
    if (!up.cases.empty()) chains.push_back(std::move(up));
    if (!down.cases.empty()) chains.push_back(std::move(down));
  }

  std::mutex progress_mutex;
  int done = 0, failed = 0;
  auto solve_case = [&](ContactWorkspace& ws, int c, const std::vector<Start>& starts) -> bool {
    const SweepCase& sc = out.cases[static_cast<std::size_t>(c)];
    bool ok = false;
    try {
      ContactRequest req;
      req.keep_grids = opt.keep_grids;
      out.elastic[c] = solve_equilibrium(model, sc.y, sc.yaw, opt.Q, ws, opt.equilibrium, starts, req);
      ok = out.elastic[c].converged;
      if (opt.rigid) out.rigid[c] = solve_rigid(model.geometry(), sc.y, sc.yaw, opt.Q);
    } catch (const std::exception& e) {
      out.errors[c] = e.what();
      out.elastic[c].y = sc.y;
      out.elastic[c].yaw = sc.yaw;
      out.elastic[c].Q = opt.Q;
      out.elastic[c].message = e.what();
    }
    std::lock_guard<std::mutex> lock(progress_mutex);
    ++done;
    if (!ok) ++failed;
    if (opt.progress) opt.progress(done, total, failed);
    return ok;
  };

  // Runs tasks 0..count-1 on the workers; each worker owns one workspace for the whole sweep.
  int threads = opt.threads > 0 ? opt.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads = std::max(1, std::min(threads, static_cast<int>(std::max(centres.size(), chains.size()))));
  out.threads = threads;
  std::vector<std::unique_ptr<ContactWorkspace>> workspaces(static_cast<std::size_t>(threads));
  for (auto& w : workspaces) w = make_workspace();
  auto run_parallel = [&](int count, const std::function<void(ContactWorkspace&, int)>& task) {
    std::atomic<int> next{0};
    auto worker = [&](int id) {
      for (int t; (t = next.fetch_add(1)) < count;) task(*workspaces[static_cast<std::size_t>(id)], t);
    };
    if (threads == 1) {
      worker(0);  // on the calling thread (a Lua strategy bound to the caller's state stays on it)
      return;
    }
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
  };
  run_parallel(static_cast<int>(centres.size()), [&](ContactWorkspace& ws, int t) { solve_case(ws, centres[t], {}); });
  run_parallel(static_cast<int>(chains.size()), [&](ContactWorkspace& ws, int t) {
    const Chain& ch = chains[static_cast<std::size_t>(t)];
    // Continuation: start each case from the straight line through the last two converged points of the
    // chain (from the last one alone after the first step).
    struct Point {
      double y, z, roll;
      std::optional<Eigen::Matrix2d> jacobian;
    };
    std::vector<Point> path;
    const EquilibriumResult& centre = out.elastic[static_cast<std::size_t>(ch.centre)];
    if (centre.converged) path.push_back({centre.y, centre.z, centre.roll, centre.jacobian});
    for (int c : ch.cases) {
      std::vector<Start> starts;
      const double yc = out.cases[static_cast<std::size_t>(c)].y;
      if (path.size() >= 2) {
        const Point& a = path[path.size() - 2];
        const Point& b = path.back();
        const double s = (b.y != a.y) ? (yc - b.y) / (b.y - a.y) : 0.0;
        starts.push_back(Start{b.z + s * (b.z - a.z), b.roll + s * (b.roll - a.roll), b.jacobian});
      }
      if (!path.empty()) starts.push_back(Start{path.back().z, path.back().roll, std::nullopt});
      if (solve_case(ws, c, starts))
        path.push_back({yc, out.elastic[c].z, out.elastic[c].roll, out.elastic[c].jacobian});
    }
  });
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace wrc
