// The C API (wrc/wrc.h): a thin layer that checks its arguments, converts them and calls the engine. Every entry
// point runs its body through `guard`, which turns every C++ exception into a status and a thread-local message.
#include "wrc/wrc.h"

#include "wrc/api/calls.hpp"
#include "wrc/core/config.hpp"
#include "wrc/core/error.hpp"
#include "wrc/core/field_record.hpp"
#include "wrc/core/options.hpp"
#include "wrc/host/terminal.hpp"
#include "wrc/lua/definitions.hpp"
#include "wrc/profile/load.hpp"
#include "wrc/profile/write.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <new>
#include <string>
#include <unordered_map>
#include <vector>

// The opaque handle types: what a handle's address stands for (the objects live in the registry).
struct wrc_profile {
  std::shared_ptr<const wrc::Profile> profile;
};

struct wrc_wheelset {
  std::shared_ptr<const wrc::Wheelset> model;
  std::mutex pool_mutex;
  std::vector<std::unique_ptr<wrc::ContactWorkspace>> pool;  // idle workspaces, one taken per call
};

struct wrc_trajectory {
  std::unique_ptr<wrc::Trajectory> trajectory;
  std::mutex mutex;  // one step at a time
};

struct wrc_result {
  struct Field {
    bool is_string = false, is_list = false, is_array = false;  // none: a number (or boolean, integer)
    double number = 0;
    std::string text;
    std::vector<double> values;  // arrays and grids
    std::size_t count = 0;       // list length
  };
  std::vector<std::string> order;  // paths in the order described
  std::unordered_map<std::string, Field> fields;
};

namespace {

thread_local std::string last_error;
// The words of this thread's messages about option types (wrc_set_option_dialect).
thread_local wrc::OptionDialect option_dialect = wrc::OptionDialect::c;
// Whether this thread's profile loads print the profile's warnings on stderr (wrc_set_profile_warnings_printed).
thread_local bool profile_warnings_printed = true;

// A status with its message, thrown inside an entry point.
struct Failure {
  wrc_status status;
  std::string message;
};

[[noreturn]] void invalid(std::string message) { throw Failure{WRC_INVALID_ARGUMENT, std::move(message)}; }

// An engine message for a C caller: without the Lua traceback that an error inside a Lua profile definition carries
// (the message is its first part; the frames name the host's internals, not the caller's input).
std::string without_traceback(std::string message) {
  const std::size_t at = message.find("\nstack traceback:");
  if (at != std::string::npos) message.erase(at);
  while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
  return message;
}

template <class F>
wrc_status guard(const char* function, F&& body) {
  // The function's name once: the engine's readers name their context, which is often the function itself.
  auto named = [function](std::string message) {
    const std::string prefix = std::string(function) + ": ";
    return message.rfind(prefix, 0) == 0 ? message : prefix + message;
  };
  try {
    last_error.clear();
    return body();
  } catch (const Failure& f) {
    last_error = named(f.message);
    return f.status;
  } catch (const wrc::Error& e) {
    last_error = named(without_traceback(e.what()));
    return WRC_ERROR;
  } catch (const std::bad_alloc&) {
    last_error = std::string(function) + ": out of memory";
    return WRC_ERROR;
  } catch (const std::exception& e) {
    last_error = std::string(function) + ": internal error: " + e.what();
    return WRC_ERROR;
  } catch (...) {
    last_error = std::string(function) + ": internal error";
    return WRC_ERROR;
  }
}

// Live handles by address, each kept alive by the registry (and by a call that uses it, so that a handle freed by
// another thread during a call is released only when the call ends).
class Registry {
 public:
  template <class T>
  T* add(std::shared_ptr<T> object) {
    std::lock_guard lock(mutex_);
    T* key = object.get();
    live_[key] = Entry{std::move(object), typeid(T).name()};
    return key;
  }
  template <class T>
  std::shared_ptr<T> get(const T* handle, const char* what) {
    if (!handle) invalid(fmt::format("the {} is NULL", what));
    std::lock_guard lock(mutex_);
    const auto it = live_.find(handle);
    if (it == live_.end() || it->second.type != typeid(T).name())
      invalid(fmt::format("the {} handle {} is not a live {} (freed, or never made)", what, static_cast<const void*>(handle), what));
    return std::static_pointer_cast<T>(it->second.object);
  }
  template <class T>
  void remove(const T* handle, const char* what) {
    get(handle, what);
    std::lock_guard lock(mutex_);
    live_.erase(handle);
  }

 private:
  struct Entry {
    std::shared_ptr<void> object;
    const char* type = "";
  };
  std::mutex mutex_;
  std::unordered_map<const void*, Entry> live_;
};

Registry& registry() {
  static Registry r;
  return r;
}

template <class T>
void set_out(T** out, const char* what) {
  if (!out) invalid(fmt::format("the output pointer for the {} is NULL", what));
  *out = nullptr;
}

void check_side(int side) {
  if (side != WRC_LEFT && side != WRC_RIGHT) invalid(fmt::format("side = {} must be WRC_LEFT (0) or WRC_RIGHT (1)", side));
}

void finite(const char* name, double v) {
  if (!std::isfinite(v)) invalid(wrc::format_message("{} = {} must be a finite number", name, v));
}

// A caller's array of n points: no array that size holds a profile or a table (and y + n would not be an address).
void check_count(std::size_t n, const char* what) {
  if (n > wrc::kMaxProfilePoints)
    invalid(fmt::format("n = {} {} is more than any profile or table has (at most {})", n, what, wrc::kMaxProfilePoints));
}

wrc::OptionTable options_of(const char* text, const char* context) {
  if (text) return wrc::parse_option_text(text, context, option_dialect);
  wrc::OptionTable none;
  none.dialect = option_dialect;  // the call's numbers join it, and their messages speak the same words
  return none;
}

// The options of a call: the caller's option text, and the numbers the call takes as arguments under the names Lua
// gives them (so that one reader, api::X::read, checks them all). An argument must be a finite number and must not be
// given again as an option.
void set_argument(wrc::OptionTable& t, const char* function, const char* name, wrc::OptionValue v) {
  if (t.find(name)) wrc::fail("{}: '{}' is an argument of {}, not an option", function, name, function);
  t.set(name, std::move(v));
}

wrc::OptionTable call_options(const char* text, const char* function,
                              std::initializer_list<std::pair<const char*, double>> arguments) {
  for (auto [name, v] : arguments) finite(name, v);
  wrc::OptionTable t = options_of(text, (std::string(function) + ": options").c_str());
  for (auto [name, v] : arguments) set_argument(t, function, name, wrc::OptionValue::of(v));
  return t;
}

// A solve's failure is the status WRC_NOT_CONVERGED with its result: the C API has no on_failure.
void no_on_failure(const wrc::OptionTable& t, const char* function) {
  if (t.find("on_failure"))
    wrc::fail("{}: 'on_failure' is not an option of the C API (a solve that fails returns WRC_NOT_CONVERGED and its "
              "result)", function);
}

// A C array as an option value (an array of numbers).
wrc::OptionValue array_value(const double* v, std::size_t n) {
  std::vector<wrc::OptionValue> a;
  a.reserve(n);
  for (std::size_t i = 0; i < n; ++i) a.push_back(wrc::OptionValue::of(v[i]));
  return wrc::OptionValue::of(std::move(a));
}

// A workspace of the wheelset's pool for the duration of one call (returned to the pool after it).
class Lease {
 public:
  explicit Lease(wrc_wheelset& w) : w_(w) {
    std::lock_guard lock(w.pool_mutex);
    if (!w.pool.empty()) {
      ws_ = std::move(w.pool.back());
      w.pool.pop_back();
    }
    if (!ws_) ws_ = w.model->make_workspace();
    ws_->forget();  // a call's result does not depend on earlier calls
  }
  ~Lease() {
    std::lock_guard lock(w_.pool_mutex);
    w_.pool.push_back(std::move(ws_));
  }
  wrc::ContactWorkspace& operator*() { return *ws_; }

 private:
  wrc_wheelset& w_;
  std::unique_ptr<wrc::ContactWorkspace> ws_;
};

wrc_result::Field& add_field(wrc_result& r, std::string path) {
  wrc_result::Field& f = r.fields[path];
  r.order.push_back(std::move(path));
  return f;
}

// A recorded result flattened into paths ("left.patches.1.force.z"), in the order recorded: a table's fields under
// "key.", a list (itself a field: its length) with its items under "key.1.", "key.2.", ...; integers and booleans
// as numbers; arrays and grids as values. A repeated path is listed again and its field updated.
void flatten(wrc::FieldRecord& record, const wrc::FieldNode& parent, const std::string& prefix, wrc_result& r) {
  using K = wrc::FieldNode::Kind;
  int items = 0;
  for (const wrc::FieldNode& c : parent.children()) {
    if (parent.kind == K::list && c.kind == K::table && c.key.empty()) {
      flatten(record, c, prefix + std::to_string(++items) + ".", r);
      continue;
    }
    std::string path = prefix;
    path += c.key;
    if (c.kind == K::table) {
      flatten(record, c, path += '.', r);
      continue;
    }
    wrc_result::Field& f = add_field(r, std::move(path));
    switch (c.kind) {
      case K::number: f.number = c.number; break;
      case K::integer: f.number = static_cast<double>(c.integer); break;
      case K::boolean: f.number = c.integer != 0 ? 1 : 0; break;
      case K::string:
        f.is_string = true;
        f.text = c.text;
        break;
      case K::numbers:
      case K::grid:
        f.is_array = true;  // also when empty: then values is, and a number's is too
        f.values = record.take_values(c);
        break;
      case K::integers:
        f.is_array = true;
        for (long long v : c.integers) f.values.push_back(static_cast<double>(v));
        break;
      case K::list:
        f.is_list = true;
        f.count = c.count;
        flatten(record, c, r.order.back() + ".", r);  // the list's path
        break;
      case K::table: break;
    }
  }
}

template <class Result, class... Extra>
wrc_status make_result(wrc_result** out, bool converged, const std::string& failure, const Result& r, Extra&&... extra) {
  auto res = std::make_shared<wrc_result>();
  wrc::record_and_convert([&](wrc::FieldRecord& record) { flatten(record, record.root(), "", *res); }, r,
                          std::forward<Extra>(extra)...);
  *out = registry().add(std::move(res));
  if (converged) return WRC_OK;
  last_error = failure;
  return WRC_NOT_CONVERGED;
}

const wrc_result::Field& field(const wrc_result* result, const char* path) {
  const auto r = registry().get(result, "result");
  if (!path) invalid("the path is NULL");
  const auto it = r->fields.find(path);
  if (it == r->fields.end()) {
    // A table is not a field of its own: its fields are ("force" holds "force.x", ...); name them.
    const std::string prefix = std::string(path) + ".";
    std::vector<std::string> inside;
    for (const std::string& p : r->order)
      if (p.compare(0, prefix.size(), prefix) == 0 && p.find('.', prefix.size()) == std::string::npos) inside.push_back(p);
    const std::size_t shown = std::min<std::size_t>(inside.size(), 8);
    if (!inside.empty() && *path)
      throw Failure{WRC_NOT_FOUND, fmt::format("'{}' is a table, not a field: its fields are {}{}", path,
                                               fmt::join(inside.begin(), inside.begin() + shown, ", "),
                                               inside.size() > shown ? ", ..." : "")};
    throw Failure{WRC_NOT_FOUND, fmt::format("the result has no field '{}'", path)};
  }
  return it->second;  // the result outlives the call: the caller may not free it meanwhile (wrc.h)
}

template <class T>
void need_output(T* p, const char* what) {
  if (!p) invalid(fmt::format("the output pointer {} is NULL", what));
}

// Entry `index` of a handle's list of strings (a result's field paths, a profile's warnings), owned by the handle:
// "index 3 is past the result's 2 fields" when there is none. `owner` and `items` name them in that message.
const char* entry(const std::vector<std::string>& list, std::size_t index, const char* owner, const char* items) {
  if (index >= list.size()) invalid(fmt::format("index {} is past the {}'s {} {}", index, owner, list.size(), items));
  return list[index].c_str();
}

// A loaded or made profile's warnings on stderr, each prefixed by `who` (also given by wrc_profile_warning), unless
// the thread turned that off (wrc_set_profile_warnings_printed).
void print_warnings(const wrc::Profile& p, const char* who) {
  if (!profile_warnings_printed) return;
  for (const std::string& w : p.warnings) std::fprintf(stderr, "%s: warning: %s\n", who, w.c_str());
}

}  // namespace

extern "C" {

const char* wrc_version(void) { return WRC_VERSION; }

int wrc_abi_version(void) { return WRC_ABI_VERSION; }

const char* wrc_last_error(void) { return last_error.c_str(); }

wrc_status wrc_set_option_dialect(const char* front_end) {
  return guard("wrc_set_option_dialect", [&] {
    const std::string_view f = front_end ? front_end : "(null)";
    if (f == "c") option_dialect = wrc::OptionDialect::c;
    else if (f == "matlab") option_dialect = wrc::OptionDialect::matlab;
    else invalid(fmt::format("front_end = \"{}\" must be \"c\" or \"matlab\"", f));
    return WRC_OK;
  });
}

wrc_status wrc_set_profile_warnings_printed(int printed) {
  return guard("wrc_set_profile_warnings_printed", [&] {
    if (printed != 0 && printed != 1) invalid(fmt::format("printed = {} must be 0 or 1", printed));
    profile_warnings_printed = printed == 1;
    return WRC_OK;
  });
}

const char* wrc_closest_name(const char* word, const char* const* names, size_t count) {
  if (!word || !names) return nullptr;
  try {
    std::vector<std::string> known;
    for (size_t i = 0; i < count; ++i) known.emplace_back(names[i] ? names[i] : "");
    const std::string near = wrc::closest_name(word, known);
    for (size_t i = 0; i < count && !near.empty(); ++i)
      if (known[i] == near) return names[i];
  } catch (...) {  // out of memory: no suggestion
  }
  return nullptr;
}

wrc_status wrc_profile_load(const char* path, const char* options, wrc_profile** out) {
  return guard("wrc_profile_load", [&] {
    set_out(out, "profile");
    if (!path) invalid("the path is NULL");
    // Lua runs only inside the definition loader, for a .lua definition (a Simpack or text file makes no Lua state).
    const wrc::DefinitionLoader definitions = wrc::lua::definition_loader();
    auto p = std::make_shared<wrc_profile>();
    p->profile = std::make_shared<const wrc::Profile>(
        wrc::load_profile(path, options_of(options, "wrc_profile_load: options"), &definitions));
    print_warnings(*p->profile, "wrc.profile.load");
    *out = registry().add(std::move(p));
    return WRC_OK;
  });
}

wrc_status wrc_profile_from_points(const char* kind, const double* y, const double* z, size_t n, const char* name,
                                   wrc_profile** out) {
  return guard("wrc_profile_from_points", [&] {
    set_out(out, "profile");
    if (!kind) invalid("the kind is NULL (\"wheel\" or \"rail\")");
    check_count(n, "points");
    if (n > 0 && (!y || !z)) invalid("the point arrays are NULL");
    const wrc::ProfileKind k = wrc::parse_profile_kind(kind, "wrc_profile_from_points");
    auto p = std::make_shared<wrc_profile>();
    p->profile = std::make_shared<const wrc::Profile>(
        wrc::points_profile(k, std::vector<double>(y, y + n), std::vector<double>(z, z + n),
                            name ? name : wrc::to_string(k), "wrc_profile_from_points"));
    print_warnings(*p->profile, "wrc");  // the text names wrc_profile_from_points
    *out = registry().add(std::move(p));
    return WRC_OK;
  });
}

wrc_status wrc_profile_points(const wrc_profile* profile, double* y, double* z, size_t capacity, size_t* n) {
  return guard("wrc_profile_points", [&] {
    need_output(n, "n");
    const auto p = registry().get(profile, "profile");
    *n = p->profile->size();
    if (capacity < *n) throw Failure{WRC_TOO_SMALL, fmt::format("the arrays hold {} values, the profile has {} points", capacity, *n)};
    if (!y || !z) invalid("the point arrays are NULL");
    std::copy(p->profile->y.begin(), p->profile->y.end(), y);
    std::copy(p->profile->z.begin(), p->profile->z.end(), z);
    return WRC_OK;
  });
}

wrc_status wrc_profile_warnings(const wrc_profile* profile, size_t* n) {
  return guard("wrc_profile_warnings", [&] {
    need_output(n, "n");
    *n = registry().get(profile, "profile")->profile->warnings.size();
    return WRC_OK;
  });
}

wrc_status wrc_profile_warning(const wrc_profile* profile, size_t index, const char** text) {
  return guard("wrc_profile_warning", [&] {
    need_output(text, "text");
    *text = entry(registry().get(profile, "profile")->profile->warnings, index, "profile", "warnings");
    return WRC_OK;
  });
}

wrc_status wrc_profile_write(const wrc_profile* profile, const char* path, const char* options) {
  return guard("wrc_profile_write", [&] {
    const auto p = registry().get(profile, "profile");
    if (!path) invalid("the path is NULL");
    wrc::write_profile(*p->profile, path, options_of(options, "wrc_profile_write: options"), "file");
    return WRC_OK;
  });
}

wrc_status wrc_profile_free(wrc_profile* profile) {
  return guard("wrc_profile_free", [&] {
    if (profile) registry().remove(profile, "profile");
    return WRC_OK;
  });
}

wrc_status wrc_wheelset_new4(const wrc_profile* left_wheel, const wrc_profile* right_wheel, const wrc_profile* left_rail,
                             const wrc_profile* right_rail, const char* options, wrc_wheelset** out) {
  return guard("wrc_wheelset_new", [&] {
    set_out(out, "wheelset");
    wrc::WheelsetProfiles profiles;
    profiles.wheel = {*registry().get(left_wheel, "left wheel profile")->profile,
                      *registry().get(right_wheel, "right wheel profile")->profile};
    profiles.rail = {*registry().get(left_rail, "left rail profile")->profile,
                     *registry().get(right_rail, "right rail profile")->profile};
    const wrc::OptionTable t = options_of(options, "wrc_wheelset_new: options");
    wrc::OptionReader r(t, "wrc_wheelset_new");
    const wrc::WheelsetParams params = read_wheelset_params(r);
    wrc::OptionTable strategy_options;
    if (const wrc::OptionValue* v = r.value("strategy_options")) {
      if (v->type != wrc::OptionValue::Type::table)
        invalid(fmt::format("'strategy_options' must be {}, got {}", r.words().a_table, r.type_name(*v)));
      strategy_options = *v->table;
    }
    r.finish();
    auto w = std::make_shared<wrc_wheelset>();
    w->model = wrc::build_wheelset(profiles, params,
                                   wrc::native_strategy(params.strategy, strategy_options, params.contact.element));
    *out = registry().add(std::move(w));
    return WRC_OK;
  });
}

wrc_status wrc_wheelset_new(const wrc_profile* wheel, const wrc_profile* rail, const char* options, wrc_wheelset** out) {
  return wrc_wheelset_new4(wheel, wheel, rail, rail, options, out);
}

wrc_status wrc_wheelset_free(wrc_wheelset* wheelset) {
  return guard("wrc_wheelset_free", [&] {
    if (wheelset) registry().remove(wheelset, "wheelset");
    return WRC_OK;
  });
}

wrc_status wrc_contact(wrc_wheelset* wheelset, double y, double z, double roll, double yaw, const char* options,
                       wrc_result** out) {
  return guard("wrc_contact", [&] {
    set_out(out, "result");
    const auto w = registry().get(wheelset, "wheelset");
    const auto t = call_options(options, "wrc_contact", {{"y", y}, {"z", z}, {"roll", roll}, {"yaw", yaw}});
    const auto call = wrc::api::read<wrc::api::ContactCall>(t, "wrc_contact");
    Lease ws(*w);
    return make_result(out, true, "", call.run(*w->model, *ws), call.request.sensitivity);
  });
}

wrc_status wrc_wheel(wrc_wheelset* wheelset, int side, double y, double yaw, double roll, double Fz, const char* options,
                     wrc_result** out) {
  return guard("wrc_wheel", [&] {
    set_out(out, "result");
    const auto w = registry().get(wheelset, "wheelset");
    check_side(side);
    auto t = call_options(options, "wrc_wheel", {{"y", y}, {"yaw", yaw}, {"roll", roll}, {"Fz", Fz}});
    no_on_failure(t, "wrc_wheel");
    set_argument(t, "wrc_wheel", "side", wrc::OptionValue::of(std::string(wrc::side_name(side))));
    const auto call = wrc::api::read<wrc::api::WheelCall>(t, "wrc_wheel");
    Lease ws(*w);
    const wrc::WheelResult res = call.run(*w->model, *ws);
    return make_result(out, res.converged, res.converged ? "" : "wrc_wheel: " + failure_message(res), res);
  });
}

wrc_status wrc_equilibrium(wrc_wheelset* wheelset, double y, double yaw, double Q, const char* options, wrc_result** out) {
  return guard("wrc_equilibrium", [&] {
    set_out(out, "result");
    const auto w = registry().get(wheelset, "wheelset");
    const auto t = call_options(options, "wrc_equilibrium", {{"y", y}, {"yaw", yaw}, {"Q", Q}});
    no_on_failure(t, "wrc_equilibrium");
    const auto call = wrc::api::read<wrc::api::EquilibriumCall>(t, "wrc_equilibrium");
    Lease ws(*w);
    const wrc::EquilibriumResult e = call.run(*w->model, *ws);
    return make_result(out, e.converged, e.converged ? "" : "wrc_equilibrium: " + failure_message(e), e);
  });
}

wrc_status wrc_subsurface(const wrc_result* result, const char* patch, const char* options, wrc_result** out) {
  return guard("wrc_subsurface", [&] {
    set_out(out, "result");
    if (!patch) invalid("the patch path is NULL");
    const std::string at = std::string(patch) + ".";
    const auto number = [&](const std::string& key) {
      const wrc_result::Field& f = field(result, (at + key).c_str());
      if (f.is_string || f.is_list || f.is_array) invalid(fmt::format("'{}{}' is not a number", at, key));
      return f.number;
    };
    const auto grid = [&](const std::string& key) {
      const auto r = registry().get(result, "result");
      const auto it = r->fields.find(at + key);
      return it == r->fields.end() ? std::vector<double>{} : it->second.values;
    };
    wrc::api::PatchLoad load;
    wrc::halfspace::Grid& g = load.grid;
    g.nx = static_cast<int>(std::clamp(number("grid.nx"), -1.0, 1e9));  // validated by the engine
    g.ny = static_cast<int>(std::clamp(number("grid.ny"), -1.0, 1e9));
    g.dx = number("grid.dx"), g.dy = number("grid.dy"), g.x0 = number("grid.x0"), g.y0 = number("grid.y0");
    load.nu = number("nu");
    load.pressure = grid("pressure");
    if (load.pressure.empty())
      invalid(fmt::format("'{}' has no pressure grid: the call that made the result must keep its grids", patch));
    load.px = grid("px");
    load.py = grid("py");
    const auto call = wrc::api::read<wrc::api::SubsurfaceCall>(options_of(options, "wrc_subsurface: options"),
                                                             "wrc_subsurface");
    return make_result(out, true, "", call.run(load));
  });
}

wrc_status wrc_rigid(wrc_wheelset* wheelset, double y, double yaw, double Q, wrc_result** out) {
  return guard("wrc_rigid", [&] {
    set_out(out, "result");
    const auto w = registry().get(wheelset, "wheelset");
    const auto t = call_options(nullptr, "wrc_rigid", {{"y", y}, {"yaw", yaw}, {"Q", Q}});
    const wrc::RigidResult r = wrc::api::read<wrc::api::RigidCall>(t, "wrc_rigid").run(*w->model);
    return make_result(out, r.converged, r.converged ? "" : "wrc_rigid: " + r.message, r);
  });
}

wrc_status wrc_trajectory_new(wrc_wheelset* wheelset, const char* options, wrc_trajectory** out) {
  return guard("wrc_trajectory_new", [&] {
    set_out(out, "trajectory");
    const auto w = registry().get(wheelset, "wheelset");
    const auto t = call_options(options, "wrc_trajectory_new", {});
    auto tr = std::make_shared<wrc_trajectory>();
    tr->trajectory = wrc::api::read<wrc::api::TrajectoryCall>(t, "wrc_trajectory_new").run(w->model);
    *out = registry().add(std::move(tr));
    return WRC_OK;
  });
}

wrc_status wrc_trajectory_contact_with(wrc_trajectory* trajectory, double y, double z, double roll, double yaw,
                                       const char* options, wrc_result** out) {
  return guard("wrc_trajectory_contact", [&] {
    set_out(out, "result");
    const auto tr = registry().get(trajectory, "trajectory");
    const auto t = call_options(options, "wrc_trajectory_contact", {{"y", y}, {"z", z}, {"roll", roll}, {"yaw", yaw}});
    const auto call = wrc::api::read<wrc::api::TrajectoryContactCall>(t, "wrc_trajectory_contact");
    std::lock_guard lock(tr->mutex);
    return make_result(out, true, "", call.run(*tr->trajectory));
  });
}

wrc_status wrc_trajectory_contact(wrc_trajectory* trajectory, double y, double z, double roll, double yaw,
                                  wrc_result** out) {
  return wrc_trajectory_contact_with(trajectory, y, z, roll, yaw, nullptr, out);
}

wrc_status wrc_trajectory_wheel_with(wrc_trajectory* trajectory, int side, double y, double yaw, double roll, double Fz,
                                     const char* options, wrc_result** out) {
  return guard("wrc_trajectory_wheel", [&] {
    set_out(out, "result");
    const auto tr = registry().get(trajectory, "trajectory");
    check_side(side);
    auto t = call_options(options, "wrc_trajectory_wheel", {{"y", y}, {"yaw", yaw}, {"roll", roll}, {"Fz", Fz}});
    set_argument(t, "wrc_trajectory_wheel", "side", wrc::OptionValue::of(std::string(wrc::side_name(side))));
    const auto call = wrc::api::read<wrc::api::TrajectoryWheelCall>(t, "wrc_trajectory_wheel");
    std::lock_guard lock(tr->mutex);
    const wrc::WheelResult res = call.run(*tr->trajectory);
    return make_result(out, res.converged, res.converged ? "" : "wrc_trajectory_wheel: " + failure_message(res), res);
  });
}

wrc_status wrc_trajectory_wheel(wrc_trajectory* trajectory, int side, double y, double yaw, double roll, double Fz,
                                wrc_result** out) {
  return wrc_trajectory_wheel_with(trajectory, side, y, yaw, roll, Fz, nullptr, out);
}

wrc_status wrc_trajectory_reset(wrc_trajectory* trajectory) {
  return guard("wrc_trajectory_reset", [&] {
    const auto t = registry().get(trajectory, "trajectory");
    std::lock_guard lock(t->mutex);
    t->trajectory->reset();
    return WRC_OK;
  });
}

wrc_status wrc_trajectory_free(wrc_trajectory* trajectory) {
  return guard("wrc_trajectory_free", [&] {
    if (trajectory) registry().remove(trajectory, "trajectory");
    return WRC_OK;
  });
}

wrc_status wrc_rigid_contact(wrc_wheelset* wheelset, double y, double yaw, const char* options, wrc_result** out) {
  return guard("wrc_rigid_contact", [&] {
    set_out(out, "result");
    const auto w = registry().get(wheelset, "wheelset");
    const auto t = call_options(options, "wrc_rigid_contact", {{"y", y}, {"yaw", yaw}});
    const wrc::RigidResult res = wrc::api::read<wrc::api::RigidCall>(t, "wrc_rigid_contact").run(*w->model);
    return make_result(out, res.converged, res.converged ? "" : "wrc_rigid_contact: " + res.message, res);
  });
}

wrc_status wrc_geometry_table(wrc_wheelset* wheelset, const char* options, wrc_result** out) {
  return guard("wrc_geometry_table", [&] {
    set_out(out, "result");
    const auto w = registry().get(wheelset, "wheelset");
    auto call = wrc::api::read<wrc::api::GeometryTableCall>(call_options(options, "wrc_geometry_table", {}),
                                                            "wrc_geometry_table");
    if (call.progress.on(false)) call.options.progress = wrc::host::progress_line("geometry table", "rows");
    return make_result(out, true, "", call.run(*w->model));
  });
}

wrc_status wrc_conicity(const double* y, const double* dr, size_t n, const char* options, wrc_result** out) {
  return guard("wrc_conicity", [&] {
    set_out(out, "result");
    check_count(n, "rows");
    if (n > 0 && (!y || !dr)) invalid("the y or dr array is NULL");
    auto t = call_options(options, "wrc_conicity", {});
    set_argument(t, "wrc_conicity", "y", array_value(y, n));
    set_argument(t, "wrc_conicity", "dr", array_value(dr, n));
    const auto call = wrc::api::read<wrc::api::ConicityCall>(t, "wrc_conicity");
    return make_result(out, true, "", call.run());
  });
}

wrc_status wrc_wheelset_conicity(wrc_wheelset* wheelset, const char* options, wrc_result** out) {
  return guard("wrc_wheelset_conicity", [&] {
    set_out(out, "result");
    const auto w = registry().get(wheelset, "wheelset");
    const auto t = call_options(options, "wrc_wheelset_conicity", {});
    return make_result(out, true, "", wrc::api::read<wrc::api::WheelsetConicityCall>(t, "wrc_wheelset_conicity").run(*w->model));
  });
}

wrc_status wrc_profile_flange_measures(const wrc_profile* profile, const char* options, wrc_result** out) {
  return guard("wrc_profile_flange_measures", [&] {
    set_out(out, "result");
    const auto p = registry().get(profile, "profile");
    const auto t = call_options(options, "wrc_profile_flange_measures", {});
    const auto call = wrc::api::read<wrc::api::FlangeMeasuresCall>(t, "wrc_profile_flange_measures");
    return make_result(out, true, "", call.run(*p->profile));
  });
}

wrc_status wrc_result_number(const wrc_result* result, const char* path, double* value) {
  return guard("wrc_result_number", [&] {
    need_output(value, "value");
    const auto& f = field(result, path);
    if (f.is_string || f.is_list || f.is_array) invalid(fmt::format("'{}' is not a number", path));
    *value = f.number;
    return WRC_OK;
  });
}

wrc_status wrc_result_count(const wrc_result* result, const char* path, size_t* n) {
  return guard("wrc_result_count", [&] {
    need_output(n, "n");
    const auto& f = field(result, path);
    if (!f.is_list && !f.is_array)
      invalid(fmt::format("'{}' is a {}, not a list or array", path, f.is_string ? "string" : "number"));
    *n = f.is_list ? f.count : f.values.size();
    return WRC_OK;
  });
}

wrc_status wrc_result_numbers(const wrc_result* result, const char* path, double* values, size_t capacity, size_t* n) {
  return guard("wrc_result_numbers", [&] {
    need_output(n, "n");
    const auto& f = field(result, path);
    if (!f.is_array) invalid(fmt::format("'{}' is not an array of numbers", path));
    *n = f.values.size();
    if (capacity < *n) throw Failure{WRC_TOO_SMALL, fmt::format("'{}' has {} values, the array holds {}", path, *n, capacity)};
    if (*n > 0 && !values) invalid("the values array is NULL");
    std::copy(f.values.begin(), f.values.end(), values);
    return WRC_OK;
  });
}

wrc_status wrc_result_string(const wrc_result* result, const char* path, char* buffer, size_t capacity, size_t* length) {
  return guard("wrc_result_string", [&] {
    need_output(length, "length");
    const auto& f = field(result, path);
    if (!f.is_string) invalid(fmt::format("'{}' is not a string", path));
    *length = f.text.size();
    if (capacity > 0) {
      if (!buffer) invalid("the buffer is NULL");
      const std::size_t k = std::min(capacity - 1, f.text.size());
      std::memcpy(buffer, f.text.data(), k);
      buffer[k] = '\0';
    }
    return WRC_OK;
  });
}

wrc_status wrc_result_fields(const wrc_result* result, size_t* n) {
  return guard("wrc_result_fields", [&] {
    need_output(n, "n");
    *n = registry().get(result, "result")->order.size();
    return WRC_OK;
  });
}

wrc_status wrc_result_field(const wrc_result* result, size_t index, const char** path) {
  return guard("wrc_result_field", [&] {
    need_output(path, "path");
    *path = entry(registry().get(result, "result")->order, index, "result", "fields");
    return WRC_OK;
  });
}

wrc_status wrc_result_free(wrc_result* result) {
  return guard("wrc_result_free", [&] {
    if (result) registry().remove(result, "result");
    return WRC_OK;
  });
}

}  // extern "C"
