// FieldSink (wrc/core/fields.hpp): a field's documentation reaches the sink's document() just before the value, and
// a sink that ignores documentation receives the same values as from the calls without it.
#include "wrc/core/fields.hpp"

#include <doctest/doctest.h>

#include <string>
#include <vector>

using namespace wrc;

namespace {

// Records "document key unit meaning" and "value key" lines in the order of the calls.
class Recorder final : public FieldSink {
 public:
  std::vector<std::string> log;
  void number(std::string_view key, double) override { put("number", key); }
  void integer(std::string_view key, long long) override { put("integer", key); }
  void boolean(std::string_view key, bool) override { put("boolean", key); }
  void string(std::string_view key, std::string_view) override { put("string", key); }
  void numbers(std::string_view key, const double*, std::size_t) override { put("numbers", key); }
  void integers(std::string_view key, const long long*, std::size_t) override { put("integers", key); }
  void grid(std::string_view key, const double*, int, int) override { put("grid", key); }
  void begin(std::string_view key) override { put("begin", key); }
  void begin_list(std::string_view key, std::size_t) override { put("begin_list", key); }
  void item() override { log.push_back("item"); }
  void end() override { log.push_back("end"); }

 protected:
  void document(std::string_view key, FieldDoc doc) override {
    log.push_back("doc " + std::string(key) + " [" + doc.unit + "] " + doc.meaning);
  }

 private:
  void put(const char* kind, std::string_view key) { log.push_back(std::string(kind) + " " + std::string(key)); }
};

void describe_sample(FieldSink& out) {
  out.number("pmax", 1e9, {"Pa", "peak pressure"});
  out.integer("regions", 2);
  out.vec3("force", Eigen::Vector3d(1, 2, 3), {"N", "force on the wheel"});
}

}  // namespace

TEST_CASE("fields: documentation reaches document() before each value, undocumented calls reach only the value") {
  Recorder r;
  describe_sample(r);
  const std::vector<std::string> expected = {
      "doc pmax [Pa] peak pressure", "number pmax", "integer regions", "doc force [N] force on the wheel",
      "begin force", "doc x [N] x component", "number x", "doc y [N] y component", "number y",
      "doc z [N] z component", "number z", "end"};
  CHECK(r.log == expected);
}
