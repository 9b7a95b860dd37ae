// Batch calls (wrc/api/batch.hpp) on the synthetic profiles of tests/geometry/geometry_fixtures.hpp:
//  - every element's result, as its fields' bytes, equals the same call made alone in a fresh workspace (what a Lua or
//    C call does), on 1 and 2 threads and with the elements in reverse order, for contact (frictionless and rolling),
//    wheel (with rolling keys), equilibrium and rigid;
//  - a failing element (NaN, a bad load) is recorded with the engine's message while the others are solved;
//  - a solve that fails: not_converged with the one-by-one call's message and its result, or a result with
//    on_failure = "return";
//  - the stop flag skips the elements not begun; the batchable keys come from the operation table.
#include "wheelset/synthetic_wheelset.hpp"
#include "wrc/api/batch.hpp"
#include "wrc/api/calls.hpp"
#include "wrc/core/error.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

using namespace wrc;

namespace {

// Records a described result as text, every number by its bits: two results are the same bytes when their texts are.
class Trace final : public FieldSink {
 public:
  std::string text;
  void number(std::string_view k, double v) override { put(k, bits(v)); }
  void integer(std::string_view k, long long v) override { put(k, std::to_string(v)); }
  void boolean(std::string_view k, bool v) override { put(k, v ? "true" : "false"); }
  void string(std::string_view k, std::string_view v) override { put(k, std::string(v)); }
  void numbers(std::string_view k, const double* v, std::size_t n) override { put(k, join(v, n)); }
  void integers(std::string_view k, const long long* v, std::size_t n) override {
    std::string s;
    for (std::size_t i = 0; i < n; ++i) s += std::to_string(v[i]) + ",";
    put(k, s);
  }
  void grid(std::string_view k, const double* v, int nx, int ny) override {
    put(k, std::to_string(nx) + "x" + std::to_string(ny) + ":" + join(v, static_cast<std::size_t>(nx) * ny));
  }
  void begin(std::string_view k) override { text += std::string(k) + "{"; }
  void begin_list(std::string_view k, std::size_t n) override { text += std::string(k) + "[" + std::to_string(n); }
  void item() override { text += "("; }
  void end() override { text += "}"; }

 private:
  static std::string bits(double v) { return std::to_string(std::bit_cast<std::uint64_t>(v)); }
  static std::string join(const double* v, std::size_t n) {
    std::string s;
    for (std::size_t i = 0; i < n; ++i) s += bits(v[i]) + ",";
    return s;
  }
  void put(std::string_view k, const std::string& v) { text += std::string(k) + "=" + v + ";"; }
};

// The same call made alone, as the Lua binding makes it: read, run in a fresh workspace, described.
std::string alone(const api::BatchInput& in, std::size_t i) {
  const Wheelset& ws = test::shared_synthetic_wheelset();
  const OptionTable t = in.element(i);
  auto workspace = ws.make_workspace();
  Trace out;
  if (in.operation == "contact") {
    const auto c = api::read<api::ContactCall>(t, in.context);
    describe(c.run(ws, *workspace), out, c.request.sensitivity);
  } else if (in.operation == "wheel") {
    describe(api::read<api::WheelCall>(t, in.context).run(ws, *workspace), out);
  } else if (in.operation == "equilibrium") {
    describe(api::read<api::EquilibriumCall>(t, in.context).run(ws, *workspace), out);
  } else {
    describe(api::read<api::RigidCall>(t, in.context).run(ws), out);
  }
  return out.text;
}

struct Traced {
  api::BatchRun run;
  std::vector<std::string> text;
};
Traced batch(const api::BatchInput& in, int threads, const std::atomic<bool>* stop = nullptr) {
  std::deque<Trace> sinks(in.count);
  Traced t;
  t.run = api::run_batch(test::shared_synthetic_wheelset(), in, [&](std::size_t i) -> FieldSink& { return sinks[i]; },
                         {threads, stop, {}});
  for (const Trace& s : sinks) t.text.push_back(s.text);
  return t;
}

api::BatchInput reversed(api::BatchInput in) {
  for (auto& c : in.columns) std::reverse(c.values.begin(), c.values.end());
  return in;
}

// Every element done and the same bytes as alone, on 1 and 2 threads and in reverse order.
void check_equals_alone(const api::BatchInput& in) {
  std::vector<std::string> expected;
  for (std::size_t i = 0; i < in.count; ++i) expected.push_back(alone(in, i));
  for (int threads : {1, 2}) {
    CAPTURE(threads);
    const Traced b = batch(in, threads);
    CHECK(b.run.threads == threads);
    for (std::size_t i = 0; i < in.count; ++i) {
      CAPTURE(i);
      CHECK(b.run.elements[i].message == "");
      CHECK(b.run.elements[i].status == api::BatchStatus::done);
      CHECK(b.text[i] == expected[i]);
    }
    const Traced r = batch(reversed(in), threads);
    for (std::size_t i = 0; i < in.count; ++i) CHECK(r.text[in.count - 1 - i] == expected[i]);
  }
}

std::vector<double> range(double from, double to, int n) {
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(from + (to - from) * i / (n - 1));
  return v;
}

api::BatchInput wheel_input(std::vector<double> ys) {
  api::BatchInput in{"wheel", "ws.wheel", {}, {}, ys.size()};
  in.shared.set("side", OptionValue::of(std::string("left"))).set("Fz", OptionValue::of(90e3));
  in.columns.push_back({"y", std::move(ys)});
  return in;
}

}  // namespace

TEST_CASE("batch: a wheel batch equals the calls made one by one, bit for bit, on any threads and in any order") {
  check_equals_alone(wheel_input(range(0, 6e-3, 7)));
}

TEST_CASE("batch: wheel and contact with rolling keys, a nested creepage column, equal the calls one by one") {
  api::BatchInput wheel = wheel_input(range(0, 4e-3, 4));
  wheel.shared.set("V", OptionValue::of(30.0)).set("mu", OptionValue::of(0.3));
  wheel.columns.push_back({"yaw", range(-2e-3, 2e-3, 4)});
  check_equals_alone(wheel);

  api::BatchInput contact{"contact", "ws.contact", {}, {}, 4};
  OptionTable creepage;
  creepage.set("eta", OptionValue::of(1e-3));
  contact.shared.set("z", OptionValue::of(-30e-6)).set("mu", OptionValue::of(0.3)).set("creepage",
                                                                                     OptionValue::of(creepage));
  contact.columns = {{"y", range(0, 3e-3, 4)}, {"creepage.xi", range(-2e-3, 2e-3, 4)}};
  check_equals_alone(contact);
  // the column's value reached the nested table beside the shared key
  const OptionTable t = contact.element(3);
  CHECK(t.find("creepage")->table->find("xi")->number == 2e-3);
  CHECK(t.find("creepage")->table->find("eta")->number == 1e-3);
}

TEST_CASE("batch: frictionless contact with sensitivities, equilibrium and rigid equal the calls one by one") {
  api::BatchInput contact{"contact", "ws.contact", {}, {}, 3};
  contact.shared.set("sensitivity", OptionValue::of(true));
  contact.columns = {{"y", range(0, 2e-3, 3)}, {"z", range(-20e-6, -40e-6, 3)}};
  check_equals_alone(contact);

  api::BatchInput eq{"equilibrium", "ws.equilibrium", {}, {}, 4};
  eq.shared.set("Q", OptionValue::of(180e3));
  eq.columns = {{"y", range(0, 6e-3, 4)}};
  check_equals_alone(eq);

  api::BatchInput rigid{"rigid", "ws.rigid", {}, {}, 5};
  rigid.columns = {{"y", range(-4e-3, 4e-3, 5)}, {"yaw", range(0, 4e-3, 5)}};
  check_equals_alone(rigid);
}

TEST_CASE("batch: a failing element is recorded with the engine's message, the others are solved") {
  api::BatchInput in = wheel_input({0, NAN, 2e-3, 1e-3});
  in.columns.push_back({"Fz", {90e3, 90e3, 90e3, -5.0}});
  const Traced b = batch(in, 2);
  using S = api::BatchStatus;
  CHECK(b.run.elements[0].status == S::done);
  CHECK(b.run.elements[2].status == S::done);
  CHECK(b.text[2] == alone(in, 2));
  CHECK(b.run.elements[1].status == S::failed);
  CHECK(b.run.elements[1].message.find("'y'") != std::string::npos);
  CHECK(b.run.elements[3].status == S::failed);
  std::string alone_message;
  try {
    alone(in, 3);
  } catch (const Error& e) {
    alone_message = e.what();
  }
  CHECK(alone_message != "");
  CHECK(b.run.elements[3].message == alone_message);
  CHECK(b.run.elements[1].input);  // the options refused: a front end's bad-argument error
  CHECK(b.run.elements[3].input);
  CHECK_FALSE(b.run.elements[0].input);

  // an error of the solve itself (a pose pressed 5 mm in): not the input's
  const api::BatchInput deep{"contact", "ws.contact", {}, {{"z", {-20e-6, -5e-3}}}, 2};
  const Traced c = batch(deep, 2);
  CHECK(c.run.elements[0].status == S::done);
  CHECK(c.run.elements[1].status == S::failed);
  CHECK(c.run.elements[1].message.find("max_penetration") != std::string::npos);
  CHECK_FALSE(c.run.elements[1].input);
}

TEST_CASE("batch: a solve that fails is not_converged with its result, or a result with on_failure = return") {
  // a load the wheel carries only deeper than max_penetration: out of reach
  api::BatchInput in = wheel_input({0.0, 5e-3});
  in.shared.set("max_penetration", OptionValue::of(5e-6));
  Traced b = batch(in, 2);
  for (std::size_t i = 0; i < 2; ++i) {
    CHECK(b.run.elements[i].status == api::BatchStatus::not_converged);
    CHECK(b.run.elements[i].message.find("ws.wheel: ") == 0);
    CHECK(b.run.elements[i].message.find("max_penetration") != std::string::npos);
    CHECK(b.text[i].find("converged=false;") != std::string::npos);
    CHECK(b.text[i] == alone(in, i));
  }
  in.shared.set("on_failure", OptionValue::of(std::string("return")));
  b = batch(in, 2);
  for (std::size_t i = 0; i < 2; ++i) {
    CHECK(b.run.elements[i].status == api::BatchStatus::done);
    CHECK(b.text[i].find("converged=false;") != std::string::npos);
  }
}

TEST_CASE("batch: the stop flag skips the elements not begun") {
  const api::BatchInput in{"rigid", "ws.rigid", {}, {{"y", range(0, 3e-3, 4)}}, 4};
  std::atomic<bool> stop{false};
  std::deque<Trace> sinks(in.count);
  const api::BatchRun run = api::run_batch(
      test::shared_synthetic_wheelset(), in,
      [&](std::size_t i) -> FieldSink& {
        stop = true;  // while element 0 runs (one thread: in order)
        return sinks[i];
      },
      {1, &stop, {}});
  CHECK(run.elements[0].status == api::BatchStatus::done);
  for (std::size_t i = 1; i < 4; ++i) CHECK(run.elements[i].status == api::BatchStatus::skipped);
}

TEST_CASE("batch: done() is told of every element run, and false skips the elements not begun") {
  const api::BatchInput in{"rigid", "ws.rigid", {}, {{"y", range(0, 3e-3, 5)}}, 5};
  std::deque<Trace> sinks(in.count);
  std::vector<std::size_t> told;
  const api::BatchRun run = api::run_batch(
      test::shared_synthetic_wheelset(), in, [&](std::size_t i) -> FieldSink& { return sinks[i]; },
      {1, nullptr, [&](std::size_t i) {
         told.push_back(i);
         CHECK(!sinks[i].text.empty());  // after the element was described
         return i < 1;                   // a front end's budget spent by the second element (one thread: in order)
       }});
  CHECK(told == std::vector<std::size_t>{0, 1});
  for (std::size_t i = 0; i < 2; ++i) CHECK(run.elements[i].status == api::BatchStatus::done);
  for (std::size_t i = 2; i < 5; ++i) CHECK(run.elements[i].status == api::BatchStatus::skipped);
}

TEST_CASE("batch: the batchable keys are the operations' number keys, and bad batches throw") {
  const auto wheel = api::batch_keys("wheel");
  for (const char* k : {"y", "yaw", "roll", "Fz", "V", "mu", "creepage.xi", "creepage.eta", "creepage.phi"})
    CHECK_MESSAGE(std::find(wheel.begin(), wheel.end(), k) != wheel.end(), k);
  for (const char* k : {"side", "on_failure", "method", "creepage"})
    CHECK_MESSAGE(std::find(wheel.begin(), wheel.end(), k) == wheel.end(), k);
  const auto contact = api::batch_keys("contact");
  for (const char* k : {"y", "z", "roll", "yaw"}) CHECK(std::find(contact.begin(), contact.end(), k) != contact.end());
  const auto eq = api::batch_keys("equilibrium");
  CHECK(std::find(eq.begin(), eq.end(), "Q") != eq.end());
  CHECK_THROWS_WITH_AS(api::batch_keys("sweep"), doctest::Contains("not an operation of batch calls"), Error);

  api::BatchInput in = wheel_input({0, 1e-3});
  in.columns.push_back({"Fz", {1e5}});
  CHECK_THROWS_WITH_AS(batch(in, 1), doctest::Contains("column 'Fz' has 1 values for 2 elements"), Error);
  in.columns.pop_back();
  in.operation = "sweep";
  CHECK_THROWS_WITH_AS(batch(in, 1), doctest::Contains("'sweep' is not an operation of batch calls"), Error);
}
