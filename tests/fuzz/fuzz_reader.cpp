// libFuzzer target for one reader plugin (compiled once per reader with WRC_FUZZ_SPEC naming its
// ReaderSpec): the reader's parser on arbitrary bytes, then the host's post-processing (finish_profile)
// on whatever it produced. Expected failures are wrc::Error / reader errors; anything else (a crash, a
// sanitizer report, another exception) is a finding.
#include "reader_support.hpp"
#include "wrc/core/error.hpp"
#include "wrc/profile/load.hpp"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace wrc::plugin {
extern const ReaderSpec WRC_FUZZ_SPEC;
}

namespace {

struct Collected {
  wrc::RawProfile raw;
  bool failed = false;
};

Collected& from(void* host) { return *static_cast<Collected*>(host); }

int on_point(void* host, double y, double z, int32_t line) {
  auto& c = from(host);
  if (!std::isfinite(y) || !std::isfinite(z)) {  // the host refuses non-finite points
    c.failed = true;
    return 1;
  }
  c.raw.y.push_back(y);
  c.raw.z.push_back(z);
  c.raw.lines.push_back(line);
  return 0;
}
void on_kind(void* host, int32_t kind) {
  if (kind == WRC_KIND_WHEEL) from(host).raw.kind = wrc::ProfileKind::wheel;
  if (kind == WRC_KIND_RAIL) from(host).raw.kind = wrc::ProfileKind::rail;
}
void on_units(void* host, double m, const char* by) {
  from(host).raw.metres_per_unit = m;
  from(host).raw.units_declared_by = by ? by : "";
}
void on_transform(void* host, const char* d) { from(host).raw.transforms.emplace_back(d ? d : ""); }
void on_metadata(void* host, const char* k, const char* v) { from(host).raw.metadata.emplace_back(k ? k : "", v ? v : ""); }
void on_reversed(void* host, int32_t axis, const char* undo) {
  if (!undo || !*undo || (axis != WRC_AXIS_Y && axis != WRC_AXIS_Z)) __builtin_trap();  // says which axis and how to undo it
  (axis == WRC_AXIS_Y ? from(host).raw.reversed.y : from(host).raw.reversed.z).emplace_back(undo);
}
void on_error(void* host, int32_t, const char* message) {
  if (!message || !*message) __builtin_trap();  // a reader error must say something
  from(host).failed = true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto& spec = wrc::plugin::WRC_FUZZ_SPEC;
  // The first byte picks the file extension (MiniProf takes the kind from it) and the kind hint.
  std::size_t n_ext = 0;
  while (spec.extensions[n_ext]) ++n_ext;
  const unsigned sel = size > 0 ? data[0] : 0;
  const std::string path = std::string("fuzz") + spec.extensions[sel % n_ext];
  const std::string_view text(reinterpret_cast<const char*>(data) + (size > 0 ? 1 : 0), size > 0 ? size - 1 : 0);

  Collected c;
  wrc_reader_sink sink{sizeof(wrc_reader_sink), &c, on_point, on_kind, on_units, on_transform, on_metadata, on_error,
                       on_reversed};
  wrc_reader_request req{sizeof(wrc_reader_request), path.c_str(), static_cast<int32_t>((sel / 4) % 3), nullptr, 0};
  const int rc = wrc::plugin::run_reader_on(spec, text, &req, &sink);
  if ((rc != 0) != c.failed) __builtin_trap();  // read's result and the error calls must agree
  if (rc != 0) return 0;
  wrc::LoadOptions o;
  if (!c.raw.kind) o.kind = wrc::ProfileKind::rail;
  try {
    const wrc::Profile p = wrc::finish_profile(std::move(c.raw), o, path, spec.id);
    for (std::size_t i = 0; i < p.size(); ++i)
      if (!std::isfinite(p.y[i]) || !std::isfinite(p.z[i]) || (i > 0 && p.y[i] < p.y[i - 1] - wrc::kDuplicateTolerance)) __builtin_trap();
  } catch (const wrc::Error&) {
  }
  return 0;
}
