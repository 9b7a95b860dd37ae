// The front end's stop flag (Ctrl-C in Python) on the calls that run many solves besides the sweeps and batches: the
// geometry table (and ws:conicity, which builds one), the strategy check and the wheelset's own strategy check of
// check_strategy = N. Set from the progress report after k units on one thread, no unit begins after it (the report
// is called k times, not more), the call throws "stopped", and a table writes no file.
#include "scratch.hpp"
#include "wheelset/synthetic_wheelset.hpp"
#include "wrc/core/error.hpp"
#include "wrc/geometry/strategy_check.hpp"
#include "wrc/kinematics/table.hpp"

#include <doctest/doctest.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

using namespace wrc;

namespace {

std::string read_text(const std::string& path) {
  std::ifstream f(path);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

// Runs `call`, expecting wrc::Error; returns its message ("" when it returned).
template <class F>
std::string error_of(F&& call) {
  try {
    call();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

GeometryTableOptions table_options(int rows) {
  GeometryTableOptions o;
  for (int i = 0; i < rows; ++i) o.y.push_back(-5e-3 + 10e-3 * i / (rows - 1));
  o.threads = 1;
  return o;
}

}  // namespace

TEST_CASE("a geometry table stopped after 7 rows begins no other row, throws and leaves its files as they were") {
  const std::string csv = test::tmp_path("stopped_table.csv");
  {
    std::ofstream(csv) << "the previous content\n";
  }
  std::atomic<bool> stop{false};
  int reported = 0;
  GeometryTableOptions o = table_options(200);
  o.csv = csv;
  o.stop = &stop;
  o.progress = [&](int done, int, int) {
    reported = done;
    if (done == 7) stop = true;
  };
  const std::string why = error_of([&] { run_geometry_table(test::shared_synthetic_wheelset().geometry(), o); });
  CHECK(why.find("geometry table: stopped") != std::string::npos);
  CHECK(reported == 7);
  CHECK(read_text(csv) == "the previous content\n");
  std::filesystem::remove(csv);

  // The same table not stopped: every row, and the file written (the stop is what cut the first one short).
  std::atomic<bool> never{false};
  o.stop = &never;
  o.progress = [&](int done, int, int) { reported = done; };
  const GeometryTable t = run_geometry_table(test::shared_synthetic_wheelset().geometry(), o);
  CHECK(reported == 200);
  CHECK(t.rows.size() == 200);
  CHECK(std::filesystem::exists(csv));
  std::filesystem::remove(csv);
}

TEST_CASE("ws:conicity's geometry table stops likewise") {
  std::atomic<bool> stop{true};  // Ctrl-C before the call began its rows
  WheelsetConicityOptions o;
  o.conicity.yhat = {2e-3};
  o.table.threads = 1;
  o.table.stop = &stop;
  const std::string why = error_of([&] { wheelset_conicity(test::shared_synthetic_wheelset().geometry(), o); });
  CHECK(why.find("geometry table: stopped") != std::string::npos);
}

TEST_CASE("a strategy check stopped after 3 poses checks no other pose and says the strategy is not checked") {
  std::atomic<bool> stop{false};
  int reported = 0;
  StrategyCheckOptions o;
  o.poses = 50;
  o.threads = 1;
  o.stop = &stop;
  o.progress = [&](int done, int, int) {
    reported = done;
    if (done == 3) stop = true;
  };
  const Wheelset& ws = test::shared_synthetic_wheelset();
  const std::string why = error_of([&] {
    check_strategy(ws.geometry(), o, [&] { return ws.geometry().strategy.make_search(); });
  });
  CHECK(why == "check_strategy: stopped after 3 of 50 poses: the strategy is not checked");
  CHECK(reported == 3);
}

TEST_CASE("a wheelset whose check_strategy is stopped is not built") {
  WheelsetParams params = test::synthetic_params();
  params.check_strategy = 1'000'000;  // hours of work, were it not stopped
  std::atomic<bool> stop{true};
  const std::string why = error_of([&] {
    build_wheelset(test::synthetic_profiles(), params, native_strategy(params.strategy), &stop);
  });
  CHECK(why == "check_strategy: stopped after 0 of 1000000 poses: the strategy is not checked");
}
