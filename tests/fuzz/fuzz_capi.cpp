// libFuzzer target for the C API (wrc/wrc.h) as a hostile or careless caller drives it: handles made, freed, freed
// twice, passed as the wrong type or never made; option strings and paths from the input; numbers including NaN,
// infinities, 1e308 and denormals; array sizes up to SIZE_MAX; result paths and capacities. The engine is compiled
// with coverage instrumentation in a WRC_FUZZ build (tests/fuzz/CMakeLists.txt), so the fuzzer sees the engine's
// branches, not only this file's.
//
// The input is text, one call per line, `op id... number... ; text` (tests/fuzz/seeds/capi has examples):
//   L p file ; options         wrc_profile_load (file: one of the sample files, or the text as a path)
//   F p kind n a b ; name      wrc_profile_from_points: n points of a wheel- or rail-like curve scaled by a, b
//   W w wheel rail ; options   wrc_wheelset_new (options from the text)
//   C w y z roll yaw ; options wrc_contact        H w side y yaw roll Fz ; options  wrc_wheel
//   E w y yaw Q ; options      wrc_equilibrium    R w y yaw Q                       wrc_rigid
//   G w y yaw ; options        wrc_rigid_contact  K n a ; options                   wrc_conicity
//   T t w ; options            wrc_trajectory_new
//   t t y z roll yaw ; options wrc_trajectory_contact_with   h t side y yaw roll Fz ; options  ..._wheel_with
//   X t                        wrc_trajectory_reset          M p ; options          wrc_profile_flange_measures
//   N p cap                    wrc_profile_points            A p index              wrc_profile_warnings/warning
//   Q r cap index ; path       wrc_result_number/count/numbers/string/field on `path`
//   V r                        every field of a result read back: all numbers finite
//   D kind id                  free a profile (0), wheelset (1), result (2), trajectory (3)
// An id picks a handle: 0-3 a slot of this input, 4-7 a freed handle, 8 NULL, 9 a handle of another type, 10 the
// address of something that is no handle. Results of the solves go to result slot 0-3 by turns.
//
// A finding is a crash, a sanitizer report, or a broken contract (__builtin_trap): a status outside wrc_status, an
// error without a message, a message with a Lua traceback or "internal error" (an exception the engine did not
// expect), WRC_OK without the output, a result holding a number that is not finite.
#include "wrc/wrc.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

namespace {

void require(bool ok) {
  if (!ok) __builtin_trap();
}

// WRC_FUZZ_TRACE=1 prints every call's status and message (to see what a seed does).
const bool kTrace = std::getenv("WRC_FUZZ_TRACE") != nullptr;

// The input line being run: a message may quote it, which is no finding.
std::string current_line;

// The contract of every call: a known status; on failure a one-line message (no Lua traceback) that is no internal
// error -- unless it only quotes the caller's text.
wrc_status check(wrc_status s) {
  if (kTrace) std::fprintf(stderr, "  status %d %s\n", static_cast<int>(s), s == WRC_OK ? "" : wrc_last_error());
  require(s >= WRC_OK && s <= WRC_TOO_SMALL);
  if (s != WRC_OK) {
    const char* m = wrc_last_error();
    require(m != nullptr && *m != '\0');
    require(std::strchr(m, '\n') == nullptr);  // the input's lines hold no newline either
    for (const char* bad : {"stack traceback", "internal error"})
      require(std::strstr(m, bad) == nullptr || current_line.find(bad) != std::string::npos);
  }
  return s;
}

// The sample profiles (written by the project, tests/data/profile/samples) and the Lua definitions.
const char* const kFiles[] = {WRC_SAMPLES "/s1002.prw", WRC_SAMPLES "/60e1_canted.prr", WRC_SAMPLES "/s1002.whl",
                              WRC_SAMPLES "/60e1_canted.ban", "profiles/s1002.lua", "profiles/60e1.lua",
                              WRC_SAMPLES "/README.md", WRC_SAMPLES, "no/such/file.prr"};
constexpr int kFileCount = sizeof kFiles / sizeof kFiles[0];

// Options that make a wheelset's solves slow (finer grids, the dense solver, brute force, checks at build): such a
// wheelset is made and misused, never solved, so that one input stays within milliseconds.
bool slow_options(const std::string& t) {
  for (const char* k : {"grid", "max_elements", "tolerance", "solver", "margin", "strategy", "check_strategy"})
    if (t.find(k) != std::string::npos) return true;
  return false;
}

// One line of the input.
struct Line {
  char op = 0;
  std::vector<std::string> tokens;
  std::string text;
  long id(std::size_t i) const { return i < tokens.size() ? std::strtol(tokens[i].c_str(), nullptr, 10) : 0; }
  double number(std::size_t i) const { return i < tokens.size() ? std::strtod(tokens[i].c_str(), nullptr) : 0.0; }
  std::size_t size(std::size_t i) const {
    return i < tokens.size() ? static_cast<std::size_t>(std::strtoull(tokens[i].c_str(), nullptr, 10)) : 0;
  }
  const char* options() const { return text.empty() ? nullptr : text.c_str(); }
};

Line parse(const std::string& s) {
  Line l;
  const std::size_t semi = s.find(';');
  const std::string head = s.substr(0, semi);
  if (semi != std::string::npos) {
    l.text = s.substr(semi + 1);
    while (!l.text.empty() && l.text.front() == ' ') l.text.erase(l.text.begin());
  }
  std::size_t i = 0;
  while (i < head.size()) {
    while (i < head.size() && head[i] == ' ') ++i;
    std::size_t j = i;
    while (j < head.size() && head[j] != ' ') ++j;
    if (j > i) {
      if (!l.op) l.op = head[i];
      else l.tokens.push_back(head.substr(i, j - i));
    }
    i = j;
  }
  return l;
}

// The handles of one input, freed at its end; the freed ones are kept as addresses to misuse.
struct Handles {
  wrc_profile* profile[4] = {};
  wrc_wheelset* wheelset[4] = {};
  bool slow[4] = {};
  wrc_result* result[4] = {};
  wrc_trajectory* trajectory[4] = {};
  std::vector<void*> freed;
  int next_result = 0;
  int foreign = 0;  // an object whose address is no handle

  template <class T>
  T* pick(T* const* slots, long id) {
    const long k = ((id % 11) + 11) % 11;
    if (k < 4) return slots[k];
    if (k < 8) return freed.empty() ? nullptr : static_cast<T*>(freed[static_cast<std::size_t>(k) % freed.size()]);
    if (k == 8) return nullptr;
    if (k == 9) return static_cast<T*>(other_than<T>());
    return reinterpret_cast<T*>(&foreign);
  }
  // A live handle of another type than T (or null).
  template <class T>
  void* other_than() const {
    const auto first = [](auto* const* slots) -> void* {
      for (int i = 0; i < 4; ++i)
        if (slots[i]) return slots[i];
      return nullptr;
    };
    void* found = nullptr;
    if (!std::is_same_v<T, wrc_profile> && !found) found = first(profile);
    if (!std::is_same_v<T, wrc_wheelset> && !found) found = first(wheelset);
    if (!std::is_same_v<T, wrc_result> && !found) found = first(result);
    if (!std::is_same_v<T, wrc_trajectory> && !found) found = first(trajectory);
    return found;
  }
  static int slot(long id) { return static_cast<int>(((id % 4) + 4) % 4); }
  wrc_result** out() {
    wrc_result** r = &result[next_result];
    next_result = (next_result + 1) % 4;
    if (*r) check(wrc_result_free(*r));
    *r = nullptr;
    return r;
  }
  template <class T, class Free>
  void release(T*& h, Free free) {
    if (!h) return;
    require(check(free(h)) == WRC_OK);
    freed.push_back(h);
    h = nullptr;
  }
  // Frees a handle that is not a slot's: a freed one, NULL, another type or none is refused -- but a freed address
  // may have been reused by a new handle (wrc.h: detected "until its address is reused"), which then is freed here and
  // forgotten by its slot.
  template <class T, class Free>
  void free_other(T* p, Free free) {
    if (check(free(p)) != WRC_OK) return;
    for (auto** slots : {reinterpret_cast<void**>(profile), reinterpret_cast<void**>(wheelset),
                         reinterpret_cast<void**>(result), reinterpret_cast<void**>(trajectory)})
      for (int i = 0; i < 4; ++i)
        if (slots[i] == p) slots[i] = nullptr;
    if (p) freed.push_back(p);
  }
  void release_all() {
    for (auto& h : result) release(h, wrc_result_free);
    for (auto& h : trajectory) release(h, wrc_trajectory_free);
    for (auto& h : wheelset) release(h, wrc_wheelset_free);
    for (auto& h : profile) release(h, wrc_profile_free);
  }
};

// Every field of a result read back: numbers and arrays finite, strings terminated.
void validate(const wrc_result* r) {
  size_t n = 0;
  if (check(wrc_result_fields(r, &n)) != WRC_OK) return;
  std::vector<double> values;
  for (size_t i = 0; i < n; ++i) {
    const char* path = nullptr;
    require(check(wrc_result_field(r, i, &path)) == WRC_OK && path);
    double v = 0;
    if (check(wrc_result_number(r, path, &v)) == WRC_OK) {
      require(std::isfinite(v));
      continue;
    }
    size_t count = 0;
    if (check(wrc_result_numbers(r, path, nullptr, 0, &count)) == WRC_TOO_SMALL) {
      values.resize(count);
      require(check(wrc_result_numbers(r, path, values.data(), values.size(), &count)) == WRC_OK);
      for (double x : values) require(std::isfinite(x));
    }
    char text[64];
    size_t length = 0;
    if (check(wrc_result_string(r, path, text, sizeof text, &length)) == WRC_OK)
      require(std::strlen(text) == std::min<size_t>(length, sizeof text - 1));
  }
}

// A wheel- (kind 0) or rail-like (1) curve of n points scaled by a (width) and b (height), or anything the numbers
// make of it (NaN, inf, folds).
void curve(int kind, std::size_t n, double a, double b, std::vector<double>& y, std::vector<double>& z) {
  y.resize(std::max<std::size_t>(n, 1));
  z.resize(y.size());
  for (std::size_t i = 0; i < n; ++i) {
    const double s = n > 1 ? static_cast<double>(i) / static_cast<double>(n - 1) : 0.0;
    y[i] = (s - 0.5) * 0.07 * a;
    z[i] = kind == 0 ? y[i] / 40 - 0.028 * b * std::exp(-std::pow((s + 0.1) / 0.15, 2)) : -y[i] * y[i] / 0.6 * b;
  }
}

void run(Handles& h, const Line& l, int& solves) {
  std::vector<double> y, z;
  const char* kinds[] = {"wheel", "rail", "tyre", nullptr};
  switch (l.op) {
    case 'L': {
      wrc_profile*& p = h.profile[Handles::slot(l.id(0))];
      h.release(p, wrc_profile_free);
      const long f = l.id(1);
      std::string path = f >= 0 && f < kFileCount ? kFiles[f] : l.text;
      std::string lower = path;
      std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
      if (lower.size() >= 4 && lower.compare(lower.size() - 4, 4, ".lua") == 0 && (f < 0 || f >= kFileCount)) return;
      // Options for the sample files only (a Lua definition's own options are the definition's business, and a path
      // from the text needs none).
      const bool file = f >= 0 && f < kFileCount && f != 4 && f != 5;
      if (check(wrc_profile_load(path.c_str(), file ? l.options() : nullptr, &p)) == WRC_OK) require(p);
      return;
    }
    case 'F': {
      wrc_profile*& p = h.profile[Handles::slot(l.id(0))];
      h.release(p, wrc_profile_free);
      std::size_t n = l.size(2);
      if (n > 4096 && n <= 1'000'000) n = 4096;  // a caller's array holds n values; beyond the limit: refused first
      const int kind = static_cast<int>(((l.id(1) % 4) + 4) % 4);
      curve(kind % 2, std::min<std::size_t>(n, 4096), l.number(3), l.number(4), y, z);
      if (check(wrc_profile_from_points(kinds[kind], y.data(), z.data(), n, l.options(), &p)) == WRC_OK) require(p);
      return;
    }
    case 'N': {
      std::size_t cap = std::min<std::size_t>(l.size(1), 8192), n = 0;
      y.resize(cap);
      z.resize(cap);
      check(wrc_profile_points(h.pick(h.profile, l.id(0)), cap ? y.data() : nullptr, cap ? z.data() : nullptr, cap, &n));
      return;
    }
    case 'A': {  // a profile's warnings: each one a non-empty string while the profile lives
      const wrc_profile* p = h.pick(h.profile, l.id(0));
      std::size_t n = 0;
      if (check(wrc_profile_warnings(p, &n)) != WRC_OK) return;
      const char* text = nullptr;
      const std::size_t index = l.size(1);
      if (check(wrc_profile_warning(p, index, &text)) == WRC_OK)
        require(index < n && text && *text);
      else
        require(index >= n);
      return;
    }
    case 'W': {
      const int k = Handles::slot(l.id(0));
      h.release(h.wheelset[k], wrc_wheelset_free);
      h.slow[k] = slow_options(l.text);
      const std::string options = h.slow[k] ? l.text : "grid=2e-3 " + l.text;  // coarse, unless the text is slow
      if (check(wrc_wheelset_new(h.pick(h.profile, l.id(1)), h.pick(h.profile, l.id(2)), options.c_str(),
                                 &h.wheelset[k])) == WRC_OK)
        require(h.wheelset[k]);
      return;
    }
    case 'M':
      if (check(wrc_profile_flange_measures(h.pick(h.profile, l.id(0)), l.options(), h.out())) == WRC_OK) validate(h.result[(h.next_result + 3) % 4]);
      return;
    case 'K': {
      std::size_t n = l.size(0);
      if (n > 4096 && n <= 1'000'000) n = 4096;
      curve(1, std::min<std::size_t>(n, 4096), 1.0, l.number(1), y, z);
      for (std::size_t i = 0; i < std::min<std::size_t>(n, 4096); ++i) z[i] *= 1e-2;  // a Δr-like function
      check(wrc_conicity(y.data(), z.data(), n, l.options(), h.out()));
      return;
    }
    case 'Q': {
      const wrc_result* r = h.pick(h.result, l.id(0));
      const char* path = l.text.c_str();
      std::size_t cap = l.size(1);
      double v = 0;
      size_t n = 0;
      check(wrc_result_number(r, path, &v));
      check(wrc_result_count(r, path, &n));
      std::vector<double> values(std::min<std::size_t>(cap, 65536));
      check(wrc_result_numbers(r, path, values.empty() ? nullptr : values.data(), cap > 65536 ? 0 : cap, &n));
      check(wrc_result_numbers(r, path, nullptr, cap, &n));  // a capacity without an array
      char text[32];
      check(wrc_result_string(r, path, cap ? text : nullptr, std::min<std::size_t>(cap, sizeof text), &n));
      const char* field = nullptr;
      check(wrc_result_field(r, l.size(2), &field));
      check(wrc_result_number(r, nullptr, &v));
      return;
    }
    case 'V':
      if (const wrc_result* r = h.result[Handles::slot(l.id(0))]) validate(r);
      return;
    case 'D': {
      // A slot's handle is freed and forgotten; anything else (freed, NULL, another type, no handle) must be refused.
      const long id = l.id(1), k = ((id % 11) + 11) % 11;
      switch (((l.id(0) % 4) + 4) % 4) {
        case 0: k < 4 ? h.release(h.profile[k], wrc_profile_free) : h.free_other(h.pick(h.profile, id), wrc_profile_free); break;
        case 1: k < 4 ? h.release(h.wheelset[k], wrc_wheelset_free) : h.free_other(h.pick(h.wheelset, id), wrc_wheelset_free); break;
        case 2: k < 4 ? h.release(h.result[k], wrc_result_free) : h.free_other(h.pick(h.result, id), wrc_result_free); break;
        default: k < 4 ? h.release(h.trajectory[k], wrc_trajectory_free) : h.free_other(h.pick(h.trajectory, id), wrc_trajectory_free);
      }
      return;
    }
    default:
      break;
  }
  // The solves: at most a few per input, and never on a wheelset whose options make them slow.
  if (++solves > 6) return;
  const long wid = l.id(0);
  wrc_wheelset* w = h.pick(h.wheelset, wid);
  if (wid >= 0 && wid < 4 && h.slow[Handles::slot(wid)]) return;
  const std::string capped = l.text + " max_evaluations=40";  // a solve's cost bounded whatever the text asks
  switch (l.op) {
    case 'C':
      if (check(wrc_contact(w, l.number(1), l.number(2), l.number(3), l.number(4), l.options(), h.out())) == WRC_OK)
        validate(h.result[(h.next_result + 3) % 4]);
      return;
    case 'H':
      check(wrc_wheel(w, static_cast<int>(l.id(1)), l.number(2), l.number(3), l.number(4), l.number(5), capped.c_str(), h.out()));
      return;
    case 'E':
      check(wrc_equilibrium(w, l.number(1), l.number(2), l.number(3), capped.c_str(), h.out()));
      return;
    case 'R':
      check(wrc_rigid(w, l.number(1), l.number(2), l.number(3), h.out()));
      return;
    case 'G':
      check(wrc_rigid_contact(w, l.number(1), l.number(2), l.options(), h.out()));
      return;
    case 'T': {
      wrc_trajectory*& t = h.trajectory[Handles::slot(l.id(1))];
      h.release(t, wrc_trajectory_free);
      if (check(wrc_trajectory_new(w, l.options(), &t)) == WRC_OK) require(t);
      return;
    }
    default:
      break;
  }
  wrc_trajectory* t = h.pick(h.trajectory, wid);
  switch (l.op) {
    case 't':
      check(wrc_trajectory_contact_with(t, l.number(1), l.number(2), l.number(3), l.number(4), l.options(), h.out()));
      return;
    case 'h':
      check(wrc_trajectory_wheel_with(t, static_cast<int>(l.id(1)), l.number(2), l.number(3), l.number(4), l.number(5),
                                      l.options(), h.out()));
      return;
    case 'X':
      check(wrc_trajectory_reset(t));
      return;
    default:
      return;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  Handles h;
  int solves = 0, lines = 0;
  std::size_t start = 0;
  while (start < input.size() && lines++ < 48) {
    std::size_t end = input.find('\n', start);
    if (end == std::string::npos) end = input.size();
    const std::string s = input.substr(start, end - start);
    if (kTrace) std::fprintf(stderr, "%s\n", s.c_str());
    current_line = s;
    if (s.find('\0') == std::string::npos) run(h, parse(s), solves);  // C strings end at the first NUL
    start = end + 1;
  }
  h.release_all();
  // A freed handle stays refused (until its address is reused by a new handle, which release_all above cannot
  // cause: nothing is made after it).
  for (void* p : h.freed) require(wrc_result_free(static_cast<wrc_result*>(p)) == WRC_INVALID_ARGUMENT);
  return 0;
}
