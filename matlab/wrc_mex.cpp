// wrc_mex.cpp -- the MEX gateway of wrc's MATLAB/Octave interface (docs/matlab.md): a thin layer over the C API
// (wrc/wrc.h), called by the +wrc package as wrc_mex(command, ...). It converts name/value pairs into the C API's
// option text, calls one wrc_* function, and reads the result by its paths into nested structs. It writes no default
// and no check of an option: the engine reads every key (a misspelt key gets its message, naming the closest key).
//
// Handles: profiles, wheelsets and trajectories are kept in a table here and given to MATLAB as uint64 ids, never as
// addresses, so that an id that was freed is refused ("wrc:freed") however the C API reuses addresses. The MEX file
// stays locked (mexLock) while a handle lives, so that `clear functions` cannot forget live handles.
//
// Errors: every failure is a C++ exception (Failure) caught in mexFunction, which calls mexErrMsgIdAndTxt only after
// every C API resource of the call was released (by the destructors on the way out). A loaded profile's warnings
// (wrc_profile_warning: what looks wrong but was accepted) become MATLAB warnings (id wrc:profileWarning) the same way,
// after the call: the MATLAB desktop does not show the library's stderr, and a warning made an error does not return.
// So does a result's contact area too narrow for the grid (a wheel's resolution_note; wrc:resolutionWarning), once per
// wheelset and its trajectories.
#include "mex.h"

#include <wrc/wrc.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace {

struct Failure {
  std::string id, message;
};

[[noreturn]] void fail(const char* id, std::string message) { throw Failure{id, std::move(message)}; }

// The C API's status as an error identifier, with the engine's message.
[[noreturn]] void fail_status(wrc_status s) {
  static const char* const ids[] = {"wrc:ok", "wrc:invalidArgument", "wrc:error", "wrc:notConverged", "wrc:notFound",
                                    "wrc:tooSmall"};
  const char* id = (s >= 0 && s <= WRC_TOO_SMALL) ? ids[s] : "wrc:error";
  fail(id, wrc_last_error());
}

void check(wrc_status s) {
  if (s != WRC_OK) fail_status(s);
}

// The warnings of this call (identifier, text), raised by mexFunction once the call is done.
std::vector<std::pair<std::string, std::string>> g_warnings;

// ---- handles ----

enum class Kind { profile, wheelset, trajectory };

const char* kind_name(Kind k) {
  return k == Kind::profile ? "profile" : k == Kind::wheelset ? "wheelset" : "trajectory";
}

struct Handle {
  Kind kind;
  void* object;
  // A wheelset's, shared by its trajectories: whether a result's contact area too narrow for the grid was warned of
  // (wrc:resolutionWarning, once per wheelset; each area's `resolved` says it every time).
  std::shared_ptr<bool> resolution_warned;
};

// Live handles by id. An id is (session << 32) | serial: the session tells this loading of the MEX file from an
// earlier one (an id kept across `clear functions` is refused, not taken for a new object).
std::map<std::uint64_t, Handle> live;
std::uint64_t session = 0, serial = 0;

void release(const Handle& h) {
  switch (h.kind) {
    case Kind::profile: wrc_profile_free(static_cast<wrc_profile*>(h.object)); break;
    case Kind::wheelset: wrc_wheelset_free(static_cast<wrc_wheelset*>(h.object)); break;
    case Kind::trajectory: wrc_trajectory_free(static_cast<wrc_trajectory*>(h.object)); break;
  }
}

void release_all() {
  // Trajectories first: each keeps its wheelset alive in the library, but they are released all the same.
  for (Kind k : {Kind::trajectory, Kind::wheelset, Kind::profile})
    for (auto& [id, h] : live)
      if (h.kind == k) release(h);
  live.clear();
}

// A session number unlike the last loading's, even within the same second of the same process.
void start_session() {
  if (session) return;
  std::random_device random;
  const auto now = std::chrono::steady_clock::now().time_since_epoch().count();
  session = (static_cast<std::uint64_t>(random()) ^ static_cast<std::uint64_t>(now)) & 0xffffffffu;
  if (!session) session = 1;
  mexAtExit(release_all);
}

mxArray* add_handle(Kind kind, void* object, std::shared_ptr<bool> resolution_warned = nullptr) {
  start_session();
  const std::uint64_t id = (session << 32) | ++serial;
  if (live.empty()) mexLock();
  live[id] = Handle{kind, object, std::move(resolution_warned)};
  mxArray* out = mxCreateNumericMatrix(1, 1, mxUINT64_CLASS, mxREAL);
  *static_cast<std::uint64_t*>(mxGetData(out)) = id;
  return out;
}

std::uint64_t id_of(const mxArray* a, const char* what) {
  if (!a || !mxIsUint64(a) || mxGetNumberOfElements(a) != 1)
    fail("wrc:type", std::string(what) + " must be a wrc object (a profile, wheelset or trajectory handle)");
  return *static_cast<const std::uint64_t*>(mxGetData(a));
}

// The live handle of id `a`, of kind `kind`; a freed id is "wrc:freed".
Handle& handle_of(const mxArray* a, Kind kind, const char* what) {
  const std::uint64_t id = id_of(a, what);
  const auto it = live.find(id);
  if (it == live.end()) {
    if ((id >> 32) == session && (id & 0xffffffffu) <= serial)
      fail("wrc:freed", std::string(what) + ": this " + kind_name(kind) + " was freed (wrc.free or delete)");
    fail("wrc:freed", std::string(what) + ": not a live wrc object (freed, or made before the MEX file was cleared)");
  }
  if (it->second.kind != kind)
    fail("wrc:type", std::string(what) + " is a " + kind_name(it->second.kind) + ", not a " + kind_name(kind));
  return it->second;
}

void* object_of(const mxArray* a, Kind kind, const char* what) { return handle_of(a, kind, what).object; }

// Frees id `a`; quietly nothing for an id already freed when `quiet` (a handle object's destructor).
void free_handle(const mxArray* a, bool quiet) {
  const std::uint64_t id = id_of(a, "wrc.free's argument");
  const auto it = live.find(id);
  if (it == live.end()) {
    if (quiet) return;
    fail("wrc:freed", "wrc.free: this object was freed already");
  }
  release(it->second);
  live.erase(it);
  if (live.empty()) mexUnlock();
}

// ---- arguments: name/value pairs and structs into keys ----

std::string text_of(const mxArray* a, const std::string& what) {
  if (!a || !mxIsChar(a) || (mxGetM(a) > 1))
    fail("wrc:type", what + " must be a character row vector (a string)");
  char* s = mxArrayToString(a);
  if (!s) fail("wrc:type", what + " is not a string MATLAB can convert");
  std::string out(s);
  mxFree(s);
  return out;
}

// The arguments of a call after its handles: name/value pairs, structs (nested ones give dotted keys) or both, in
// the order given.
struct Arguments {
  std::vector<std::pair<std::string, const mxArray*>> entries;
  std::string function;  // "wrc.contact", for messages

  // A struct's fields as keys under `prefix`. The depth is bounded here only to keep the recursion off the stack's end;
  // the engine refuses keys nested deeper than it reads, with its message.
  void add_struct(const mxArray* s, const std::string& prefix, int depth = 0) {
    if (depth > 64) fail("wrc:usage", function + ": the options struct nests more than 64 levels (" + prefix + ")");
    if (mxGetNumberOfElements(s) != 1)
      fail("wrc:type", function + ": an options struct must be 1x1 (" + (prefix.empty() ? "the struct" : prefix) + ")");
    for (int f = 0; f < mxGetNumberOfFields(s); ++f) {
      const std::string key = prefix + mxGetFieldNameByNumber(s, f);
      const mxArray* v = mxGetFieldByNumber(s, 0, f);
      if (v && mxIsStruct(v)) add_struct(v, key + ".", depth + 1);
      else entries.emplace_back(key, v);
    }
  }

  Arguments(const mxArray* const* a, int n, std::string fn) : function(std::move(fn)) {
    for (int i = 0; i < n;) {
      if (mxIsStruct(a[i])) {
        add_struct(a[i], "");
        ++i;
        continue;
      }
      const std::string key = text_of(a[i], function + ": argument " + std::to_string(i + 1) + " (an option name)");
      if (i + 1 >= n) fail("wrc:usage", function + ": the option '" + key + "' has no value (name/value pairs)");
      if (mxIsStruct(a[i + 1])) add_struct(a[i + 1], key + ".");
      else entries.emplace_back(key, a[i + 1]);
      i += 2;
    }
  }

  // The names given and not taken, for a message about a missing one (a misspelt name is among them): "" when none,
  // else "; the other names given: 'q', 'grids'".
  std::string others() const {
    std::string list;
    for (const auto& e : entries) list += (list.empty() ? "'" : ", '") + e.first + "'";
    return list.empty() ? "" : "; the other names given: " + list;
  }

  // For a message about missing names: "did you mean 'y' for 'yy'? " when a name given and not taken is plausibly a
  // misspelling of one of `missing` (the engine's rule, wrc_closest_name, as for a misspelt option), else "".
  std::string misspelt(const std::vector<const char*>& missing) const {
    for (const auto& e : entries)
      if (const char* near = wrc_closest_name(e.first.c_str(), missing.data(), missing.size()))
        return std::string("did you mean '") + near + "' for '" + e.first + "'? ";
    return "";
  }

  // Removes and returns the value of `key` (null when not given).
  const mxArray* take(const char* key) {
    for (auto it = entries.begin(); it != entries.end(); ++it)
      if (it->first == key) {
        const mxArray* v = it->second;
        entries.erase(it);
        return v;
      }
    return nullptr;
  }
};

bool is_real_numeric(const mxArray* v) {
  return v && (mxIsDouble(v) || mxIsSingle(v) || mxIsInt8(v) || mxIsInt16(v) || mxIsInt32(v) || mxIsInt64(v) ||
               mxIsUint8(v) || mxIsUint16(v) || mxIsUint32(v)) &&
         !mxIsComplex(v) && !mxIsSparse(v);
}

template <class T>
void copy_as_double(const mxArray* v, std::vector<double>& out) {
  const T* p = static_cast<const T*>(mxGetData(v));
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = static_cast<double>(p[i]);
}

// A value's class as a message names it: "sparse double", "complex double", "uint64".
std::string class_words(const mxArray* v) {
  if (!v) return "nothing";
  return std::string(mxIsSparse(v) ? "sparse " : "") + (mxIsComplex(v) ? "complex " : "") + mxGetClassName(v);
}

std::vector<double> numbers_of(const mxArray* v, const std::string& what) {
  if (!is_real_numeric(v) && !(v && mxIsLogical(v)))
    fail("wrc:type", what + " must be real numbers (got " + class_words(v) +
                         (v && mxIsUint64(v) ? ", the class of wrc objects' ids: give numbers as double" : "") + ")");
  if (mxGetNumberOfDimensions(v) > 2 || (mxGetM(v) > 1 && mxGetN(v) > 1))
    fail("wrc:type", what + " must be a scalar or a vector, not a matrix");
  std::vector<double> out(mxGetNumberOfElements(v));
  switch (mxGetClassID(v)) {
    case mxDOUBLE_CLASS: copy_as_double<double>(v, out); break;
    case mxSINGLE_CLASS: copy_as_double<float>(v, out); break;
    case mxLOGICAL_CLASS: copy_as_double<mxLogical>(v, out); break;
    case mxINT8_CLASS: copy_as_double<std::int8_t>(v, out); break;
    case mxUINT8_CLASS: copy_as_double<std::uint8_t>(v, out); break;
    case mxINT16_CLASS: copy_as_double<std::int16_t>(v, out); break;
    case mxUINT16_CLASS: copy_as_double<std::uint16_t>(v, out); break;
    case mxINT32_CLASS: copy_as_double<std::int32_t>(v, out); break;
    case mxUINT32_CLASS: copy_as_double<std::uint32_t>(v, out); break;
    case mxINT64_CLASS: copy_as_double<std::int64_t>(v, out); break;
    default: fail("wrc:type", what + " must be real numbers (got " + mxGetClassName(v) + ")");
  }
  return out;
}

double number_of(const mxArray* v, const std::string& what) {
  const std::vector<double> x = numbers_of(v, what);
  if (x.size() != 1) fail("wrc:type", what + " must be one number (got " + std::to_string(x.size()) + " values)");
  return x[0];
}

std::string format_number(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

// One key=value of the option text. The text separates pairs by blanks and ';': a word holding one cannot be given.
std::string option_pair(const std::string& function, const std::string& key, const mxArray* v) {
  const std::string what = function + ": the value of '" + key + "'";
  if (key.empty() || key.find_first_of(" \t\r\n;=") != std::string::npos)
    fail("wrc:usage", function + ": '" + key + "' is not an option name");
  if (!v) fail("wrc:type", what + " is missing");
  if (mxIsUint64(v))  // a handle's id, or a number of the class ids have
    fail("wrc:type", what + " is a uint64 (a wrc object, or a number of the class of their ids); this option takes a "
                            "number (double or another numeric class), true/false or a word");
  if (mxIsChar(v)) {
    const std::string s = text_of(v, what);
    if (s.find_first_of(" \t\r\n;") != std::string::npos)
      fail("wrc:usage", what + " ('" + s + "') holds a blank or ';', which the C API's option text cannot carry");
    return key + "=" + s;
  }
  if (mxIsLogical(v)) {
    if (mxGetNumberOfElements(v) != 1) fail("wrc:type", what + " must be one true or false");
    return key + "=" + (mxIsLogicalScalarTrue(v) ? "true" : "false");
  }
  const std::vector<double> x = numbers_of(v, what);
  if (x.empty()) fail("wrc:type", what + " is empty");
  std::string text = key + "=";
  for (std::size_t i = 0; i < x.size(); ++i) text += (i ? "," : "") + format_number(x[i]);
  return text;
}

std::string option_text(const Arguments& args) {
  std::string text;
  for (const auto& [key, v] : args.entries) text += (text.empty() ? "" : " ") + option_pair(args.function, key, v);
  return text;
}

// A side given as 'left' or 'right'.
int side_of(const Arguments& a, const mxArray* v) {
  const std::string s = text_of(v, a.function + ": side");
  if (s == "left") return WRC_LEFT;
  if (s == "right") return WRC_RIGHT;
  fail("wrc:usage", a.function + ": side = '" + s + "' must be 'left' or 'right'");
}

// The arguments a C function takes positionally, read by name in its order: each required (the C API has no default
// for them, nor does this layer). Numbers, and "side" as WRC_LEFT or WRC_RIGHT.
template <std::size_t N>
std::array<double, N> positional(Arguments& a, const char* c_function, const char* const (&keys)[N]) {
  std::string all;  // "y, z, roll and yaw"
  for (std::size_t k = 0; k < N; ++k) all += (k == 0 ? "" : k + 1 < N ? ", " : " and ") + std::string(keys[k]);
  std::array<const mxArray*, N> given{};
  std::vector<const char*> missing;
  for (std::size_t k = 0; k < N; ++k)
    if (!(given[k] = a.take(keys[k]))) missing.push_back(keys[k]);
  if (!missing.empty()) {
    const std::string key = missing.front();
    fail("wrc:missingArgument", a.function + ": '" + key + "' is missing (" + a.misspelt(missing) + c_function +
                                    " takes " + all + (key == "side" ? "" : " as arguments: give each") + a.others() +
                                    ")");
  }
  std::array<double, N> values{};
  for (std::size_t k = 0; k < N; ++k) {
    const std::string key = keys[k];
    values[k] = key == "side" ? side_of(a, given[k]) : number_of(given[k], a.function + ": '" + key + "'");
  }
  return values;
}

// ---- results: paths into nested structs ----

// A result handle released at the end of the call.
struct Result {
  wrc_result* r = nullptr;
  ~Result() { wrc_result_free(r); }
};

struct Node {
  enum Type { table, list, leaf } type = table;
  std::string name;
  std::vector<std::unique_ptr<Node>> children;  // a table's fields in order; a list's items (tables)
  mxArray* value = nullptr;                     // a leaf's
  bool array = false;                           // a leaf of numbers (an array or a grid)

  Node* child(const std::string& key) {
    for (auto& c : children)
      if (c->name == key) return c.get();
    children.push_back(std::make_unique<Node>());
    children.back()->name = key;
    return children.back().get();
  }
  Node* item(std::size_t k) {  // 1-based
    while (children.size() < k) children.push_back(std::make_unique<Node>());
    return children[k - 1].get();
  }
  const Node* find(const std::string& key) const {
    for (auto& c : children)
      if (c->name == key) return c.get();
    return nullptr;
  }
};

// The value at `path`: a number, an array, a string or a list (its items come as paths of their own). Booleans and
// integers read as numbers. An empty array reads as the number 0: the C API does not tell them apart.
void read_field(const wrc_result* r, const char* path, Node& n) {
  double x = 0;
  if (wrc_result_number(r, path, &x) == WRC_OK) {
    n.type = Node::leaf;
    n.value = mxCreateDoubleScalar(x);
    return;
  }
  std::size_t count = 0;
  const wrc_status s = wrc_result_numbers(r, path, nullptr, 0, &count);
  if (s == WRC_OK || s == WRC_TOO_SMALL) {
    n.type = Node::leaf;
    n.array = true;
    n.value = mxCreateDoubleMatrix(count, 1, mxREAL);
    check(wrc_result_numbers(r, path, mxGetPr(n.value), count, &count));
    return;
  }
  std::size_t length = 0;
  if (wrc_result_string(r, path, nullptr, 0, &length) == WRC_OK) {
    std::string text(length + 1, '\0');
    check(wrc_result_string(r, path, text.data(), text.size(), &length));
    n.type = Node::leaf;
    n.value = mxCreateString(text.c_str());
    return;
  }
  check(wrc_result_count(r, path, &count));
  n.type = Node::list;
  n.item(count);  // the items' fields come as paths of their own, after the list's
}

// Inserts `path` ("left.patches.1.pmax") into the tree: a numeric part indexes the list it follows.
void insert(const wrc_result* r, Node& root, const std::string& path) {
  Node* at = &root;
  std::size_t start = 0;
  for (;;) {
    const std::size_t dot = std::min(path.find('.', start), path.size());
    const std::string part = path.substr(start, dot - start);
    if (at->type == Node::list) {
      char* end = nullptr;
      const unsigned long k = std::strtoul(part.c_str(), &end, 10);
      if (part.empty() || *end || k == 0) fail("wrc:internal", "result path '" + path + "': '" + part + "' is no list index");
      at = at->item(k);
    } else {
      at = at->child(part);
    }
    if (dot == path.size()) break;
    start = dot + 1;
  }
  read_field(r, path.c_str(), *at);
}

mxArray* to_mx(const Node& n);

// A grid of nx x ny values (element (i, j) at i + nx j) as an ny x nx matrix: M(j, i), rows along the grid's y.
mxArray* as_grid(const mxArray* v, std::size_t nx, std::size_t ny) {
  mxArray* m = mxCreateDoubleMatrix(ny, nx, mxREAL);
  const double* in = mxGetPr(v);
  double* out = mxGetPr(m);
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) out[j + ny * i] = in[i + nx * j];
  return m;
}

// The grid size of a table holding grid.nx and grid.ny (a contact area), or 0.
std::size_t grid_size(const Node& table, std::size_t& nx, std::size_t& ny) {
  const Node* g = table.find("grid");
  const Node* x = g ? g->find("nx") : nullptr;
  const Node* y = g ? g->find("ny") : nullptr;
  if (!x || !y || x->type != Node::leaf || y->type != Node::leaf || x->array || y->array) return 0;
  nx = static_cast<std::size_t>(mxGetScalar(x->value));
  ny = static_cast<std::size_t>(mxGetScalar(y->value));
  return nx * ny;
}

mxArray* table_to_mx(const Node& n) {
  std::vector<const char*> names;
  for (auto& c : n.children) names.push_back(c->name.c_str());
  mxArray* s = mxCreateStructMatrix(1, 1, static_cast<int>(names.size()), names.data());
  std::size_t nx = 0, ny = 0;
  const std::size_t cells = grid_size(n, nx, ny);
  for (std::size_t f = 0; f < n.children.size(); ++f) {
    const Node& c = *n.children[f];
    mxArray* v = (c.array && cells > 0 && mxGetNumberOfElements(c.value) == cells) ? as_grid(c.value, nx, ny) : to_mx(c);
    mxSetFieldByNumber(s, 0, static_cast<int>(f), v);
  }
  return s;
}

// A list as a 1 x n struct array: the items' fields united in order of appearance, [] where an item has none.
mxArray* list_to_mx(const Node& n) {
  std::vector<std::string> names;
  for (auto& item : n.children)
    for (auto& c : item->children)
      if (std::find(names.begin(), names.end(), c->name) == names.end()) names.push_back(c->name);
  std::vector<const char*> cnames;
  for (auto& s : names) cnames.push_back(s.c_str());
  mxArray* s = mxCreateStructMatrix(1, n.children.size(), static_cast<int>(cnames.size()), cnames.data());
  for (std::size_t k = 0; k < n.children.size(); ++k) {
    mxArray* item = table_to_mx(*n.children[k]);
    for (int f = 0; f < mxGetNumberOfFields(item); ++f) {
      const int at = mxGetFieldNumber(s, mxGetFieldNameByNumber(item, f));
      mxSetFieldByNumber(s, k, at, mxDuplicateArray(mxGetFieldByNumber(item, 0, f)));
    }
    mxDestroyArray(item);
  }
  return s;
}

mxArray* to_mx(const Node& n) {
  switch (n.type) {
    case Node::leaf: return mxDuplicateArray(n.value);
    case Node::list: return list_to_mx(n);
    default: return table_to_mx(n);
  }
}

void destroy(Node& n) {
  if (n.value) mxDestroyArray(n.value);
  n.value = nullptr;
  for (auto& c : n.children)
    if (c) destroy(*c);
}

mxArray* result_struct(const wrc_result* r) {
  std::size_t n = 0;
  check(wrc_result_fields(r, &n));
  Node root;
  for (std::size_t i = 0; i < n; ++i) {
    const char* path = nullptr;
    check(wrc_result_field(r, i, &path));
    insert(r, root, path);
  }
  mxArray* s = table_to_mx(root);
  destroy(root);
  return s;
}

// The first wheel's resolution_note of a result (a contact area too narrow for the grid: the engine's text), or "".
std::string resolution_note(const wrc_result* r) {
  const std::string name = ".resolution_note";  // the top level's (wrc.wheel) or a wheel's (left.resolution_note)
  std::size_t n = 0;
  check(wrc_result_fields(r, &n));
  for (std::size_t i = 0; i < n; ++i) {
    const char* path = nullptr;
    check(wrc_result_field(r, i, &path));
    const std::string p = std::string(".") + path;
    if (p.size() < name.size() || p.compare(p.size() - name.size(), name.size(), name) != 0) continue;
    std::size_t length = 0;
    check(wrc_result_string(r, path, nullptr, 0, &length));
    std::string text(length + 1, '\0');
    check(wrc_result_string(r, path, text.data(), text.size(), &length));
    text.resize(length);
    return text;
  }
  return "";
}

// ---- commands ----

// A call of a command: its outputs, its arguments after the command name, and the function its messages name.
struct Call {
  int nlhs;
  mxArray** plhs;
  int nrhs;
  const mxArray* const* prhs;  // after the command name
  const char* function;        // "wrc.contact"

  const mxArray* at(int i, const char* what) const {
    if (i >= nrhs) fail("wrc:usage", std::string("missing argument: ") + what);
    return prhs[i];
  }
  Arguments args(int from) const {
    return Arguments(prhs + std::min(from, nrhs), std::max(0, nrhs - from), function);
  }
  // The first argument: a live object of `kind`.
  template <class T>
  T* object(Kind kind) const {
    return static_cast<T*>(object_of(at(0, (std::string("a ") + kind_name(kind)).c_str()), kind, function));
  }
  // The result of `call(&result)` as the first output.
  template <class F>
  void result(F&& call) const {
    Result res;
    check(call(&res.r));
    plhs[0] = result_struct(res.r);
  }
  // A solve's outputs: its result struct; a solve that did not converge is an error unless the caller asked for the
  // second output (ok = false then, the result holds converged = 0 and error). With the wheelset's `warned`, a
  // contact area too narrow for the grid is a warning wrc:resolutionWarning, once per wheelset.
  template <class F>
  void solved(F&& solve, bool* warned = nullptr) const {
    Result res;
    const wrc_status s = solve(&res.r);
    if (s != WRC_OK && s != WRC_NOT_CONVERGED) fail_status(s);
    const std::string message = s == WRC_NOT_CONVERGED ? wrc_last_error() : "";
    if (s == WRC_NOT_CONVERGED && nlhs < 2) fail("wrc:notConverged", message);
    if (warned && !*warned)
      if (const std::string note = resolution_note(res.r); !note.empty()) {
        *warned = true;
        g_warnings.emplace_back(
            "wrc:resolutionWarning",
            std::string(function) + ": " + note + " (shown once per wheelset; each area's `resolved` says it)");
      }
    plhs[0] = result_struct(res.r);
    if (nlhs >= 2) plhs[1] = mxCreateLogicalScalar(s == WRC_OK);
  }
};

// The once-per-wheelset flag of the call's wheelset or trajectory (its first argument, checked by the command).
bool* warned(const Call& c) {
  const auto it = live.find(id_of(c.at(0, "a wheelset"), c.function));
  return it != live.end() && it->second.resolution_warned ? it->second.resolution_warned.get() : nullptr;
}

// A made profile's warnings (wrc_profile_warning), raised after the call.
void collect_warnings(const wrc_profile* p) {
  size_t n = 0;
  check(wrc_profile_warnings(p, &n));
  for (size_t i = 0; i < n; ++i) {
    const char* text = nullptr;
    check(wrc_profile_warning(p, i, &text));
    g_warnings.emplace_back("wrc:profileWarning", text);
  }
}

void profile_load(const Call& c) {
  const std::string path = text_of(c.at(0, "the profile's path"), std::string(c.function) + ": the path");
  const Arguments a = c.args(1);
  wrc_profile* p = nullptr;
  check(wrc_profile_load(path.c_str(), option_text(a).c_str(), &p));
  c.plhs[0] = add_handle(Kind::profile, p);
  collect_warnings(p);
}

constexpr const char* kPointsKeys[] = {"kind", "y", "z", "name"};

void profile_points(const Call& c) {
  Arguments a = c.args(0);
  const mxArray* kind = a.take("kind");
  const mxArray* y = a.take("y");
  const mxArray* z = a.take("z");
  const mxArray* name = a.take("name");
  if (!a.entries.empty()) {
    const char* near = wrc_closest_name(a.entries[0].first.c_str(), kPointsKeys, std::size(kPointsKeys));
    fail("wrc:usage", "wrc.profile.points: unknown key '" + a.entries[0].first + "' (" +
                          (near ? std::string("did you mean '") + near + "'? " : "") + "kind, y, z, name)");
  }
  if (!kind || !y || !z) fail("wrc:missingArgument", "wrc.profile.points: kind, y and z are required");
  const std::string k = text_of(kind, "wrc.profile.points: kind");
  const std::vector<double> yv = numbers_of(y, "wrc.profile.points: y"), zv = numbers_of(z, "wrc.profile.points: z");
  if (yv.size() != zv.size())
    fail("wrc:usage", "wrc.profile.points: y has " + std::to_string(yv.size()) + " values, z " + std::to_string(zv.size()));
  const std::string nm = name ? text_of(name, "wrc.profile.points: name") : "";
  wrc_profile* p = nullptr;
  check(wrc_profile_from_points(k.c_str(), yv.data(), zv.data(), yv.size(), name ? nm.c_str() : nullptr, &p));
  c.plhs[0] = add_handle(Kind::profile, p);
  collect_warnings(p);
}

void points(const Call& c) {
  const auto* p = c.object<const wrc_profile>(Kind::profile);
  std::size_t n = 0;
  const wrc_status s = wrc_profile_points(p, nullptr, nullptr, 0, &n);
  if (s != WRC_OK && s != WRC_TOO_SMALL) fail_status(s);
  mxArray* y = mxCreateDoubleMatrix(n, 1, mxREAL);
  mxArray* z = mxCreateDoubleMatrix(n, 1, mxREAL);
  check(wrc_profile_points(p, mxGetPr(y), mxGetPr(z), n, &n));
  c.plhs[0] = y;
  if (c.nlhs > 1) c.plhs[1] = z;
}

void write(const Call& c) {
  const auto* p = c.object<const wrc_profile>(Kind::profile);
  const std::string path = text_of(c.at(1, "the file's path"), std::string(c.function) + ": the path");
  const Arguments a = c.args(2);
  check(wrc_profile_write(p, path.c_str(), option_text(a).c_str()));
}

void flange_measures(const Call& c) {
  const auto* p = static_cast<const wrc_profile*>(object_of(c.at(0, "a profile"), Kind::profile, "flange_measures"));
  const Arguments a = c.args(1);
  c.result([&](wrc_result** r) { return wrc_profile_flange_measures(p, option_text(a).c_str(), r); });
}

void wheelset(const Call& c) {
  Arguments a = c.args(0);
  const char* keys[6] = {"wheel", "rail", "left_wheel", "right_wheel", "left_rail", "right_rail"};
  const wrc_profile* p[6] = {};
  for (int k = 0; k < 6; ++k)
    if (const mxArray* v = a.take(keys[k]))
      p[k] = static_cast<const wrc_profile*>(object_of(v, Kind::profile, (std::string("wrc.wheelset: ") + keys[k]).c_str()));
  const bool two = p[0] || p[1], four = p[2] || p[3] || p[4] || p[5];
  if (two == four || (two && !(p[0] && p[1])) || (four && !(p[2] && p[3] && p[4] && p[5]))) {
    std::vector<const char*> missing;
    for (int k = 0; k < 6; ++k)
      if (!p[k] && (k < 2 ? !four : !two)) missing.push_back(keys[k]);
    const std::string near = a.misspelt(missing);
    fail("wrc:missingArgument",
         "wrc.wheelset: give wheel and rail, or left_wheel, right_wheel, left_rail and right_rail (" + near +
             "profiles" + a.others() + ")");
  }
  const std::string text = option_text(a);
  wrc_wheelset* ws = nullptr;
  check(two ? wrc_wheelset_new(p[0], p[1], text.c_str(), &ws)
            : wrc_wheelset_new4(p[2], p[3], p[4], p[5], text.c_str(), &ws));
  c.plhs[0] = add_handle(Kind::wheelset, ws, std::make_shared<bool>(false));
}

void contact(const Call& c) {
  wrc_wheelset* ws = c.object<wrc_wheelset>(Kind::wheelset);
  Arguments a = c.args(1);
  const auto [y, z, roll, yaw] = positional(a, "wrc_contact", {"y", "z", "roll", "yaw"});
  c.solved([&](wrc_result** r) { return wrc_contact(ws, y, z, roll, yaw, option_text(a).c_str(), r); }, warned(c));
}

void wheel(const Call& c) {
  wrc_wheelset* ws = c.object<wrc_wheelset>(Kind::wheelset);
  Arguments a = c.args(1);
  const auto [side, y, yaw, roll, Fz] = positional(a, "wrc_wheel", {"side", "y", "yaw", "roll", "Fz"});
  c.solved(
      [&](wrc_result** r) {
        return wrc_wheel(ws, static_cast<int>(side), y, yaw, roll, Fz, option_text(a).c_str(), r);
      },
      warned(c));
}

void equilibrium(const Call& c) {
  wrc_wheelset* ws = c.object<wrc_wheelset>(Kind::wheelset);
  Arguments a = c.args(1);
  const auto [y, yaw, Q] = positional(a, "wrc_equilibrium", {"y", "yaw", "Q"});
  c.solved([&](wrc_result** r) { return wrc_equilibrium(ws, y, yaw, Q, option_text(a).c_str(), r); }, warned(c));
}

void rigid(const Call& c) {
  wrc_wheelset* ws = c.object<wrc_wheelset>(Kind::wheelset);
  Arguments a = c.args(1);
  const auto [y, yaw] = positional(a, "wrc_rigid_contact", {"y", "yaw"});
  c.solved([&](wrc_result** r) { return wrc_rigid_contact(ws, y, yaw, option_text(a).c_str(), r); });
}

void geometry_table(const Call& c) {
  wrc_wheelset* ws = c.object<wrc_wheelset>(Kind::wheelset);
  const Arguments a = c.args(1);
  c.result([&](wrc_result** r) { return wrc_geometry_table(ws, option_text(a).c_str(), r); });
}

void wheelset_conicity(const Call& c) {
  wrc_wheelset* ws = c.object<wrc_wheelset>(Kind::wheelset);
  const Arguments a = c.args(1);
  c.result([&](wrc_result** r) { return wrc_wheelset_conicity(ws, option_text(a).c_str(), r); });
}

void conicity(const Call& c) {
  Arguments a = c.args(0);
  const mxArray* y = a.take("y");
  const mxArray* dr = a.take("dr");
  if (!y || !dr) {
    std::vector<const char*> missing;
    if (!y) missing.push_back("y");
    if (!dr) missing.push_back("dr");
    const std::string near = a.misspelt(missing);
    fail("wrc:missingArgument", "wrc.conicity: 'y' and 'dr' (the Δr table, m) are required" +
                                    (a.entries.empty() ? std::string() : " (" + near + a.others().substr(2) + ")"));
  }
  const std::vector<double> yv = numbers_of(y, "wrc.conicity: y"), dv = numbers_of(dr, "wrc.conicity: dr");
  if (yv.size() != dv.size())
    fail("wrc:usage", "wrc.conicity: y has " + std::to_string(yv.size()) + " values, dr " + std::to_string(dv.size()));
  c.result([&](wrc_result** r) { return wrc_conicity(yv.data(), dv.data(), yv.size(), option_text(a).c_str(), r); });
}

void trajectory(const Call& c) {
  wrc_wheelset* ws = c.object<wrc_wheelset>(Kind::wheelset);
  const Arguments a = c.args(1);
  wrc_trajectory* tr = nullptr;
  check(wrc_trajectory_new(ws, option_text(a).c_str(), &tr));
  c.plhs[0] = add_handle(Kind::trajectory, tr, handle_of(c.prhs[0], Kind::wheelset, c.function).resolution_warned);
}

void trajectory_contact(const Call& c) {
  wrc_trajectory* tr = c.object<wrc_trajectory>(Kind::trajectory);
  Arguments a = c.args(1);
  const auto [y, z, roll, yaw] = positional(a, "wrc_trajectory_contact_with", {"y", "z", "roll", "yaw"});
  c.solved([&](wrc_result** r) { return wrc_trajectory_contact_with(tr, y, z, roll, yaw, option_text(a).c_str(), r); },
           warned(c));
}

void trajectory_wheel(const Call& c) {
  wrc_trajectory* tr = c.object<wrc_trajectory>(Kind::trajectory);
  Arguments a = c.args(1);
  const auto [side, y, yaw, roll, Fz] = positional(a, "wrc_trajectory_wheel_with", {"side", "y", "yaw", "roll", "Fz"});
  c.solved(
      [&](wrc_result** r) {
        return wrc_trajectory_wheel_with(tr, static_cast<int>(side), y, yaw, roll, Fz, option_text(a).c_str(), r);
      },
      warned(c));
}

void trajectory_reset(const Call& c) { check(wrc_trajectory_reset(c.object<wrc_trajectory>(Kind::trajectory))); }

void free_command(const Call& c) {
  const bool quiet = c.nrhs > 1 && mxIsLogicalScalarTrue(c.prhs[1]);
  free_handle(c.at(0, "the object to free"), quiet);
}

void kind(const Call& c) {
  const std::uint64_t id = id_of(c.at(0, "an object"), "kind's argument");
  const auto it = live.find(id);
  c.plhs[0] = mxCreateString(it == live.end() ? "freed" : kind_name(it->second.kind));
}

void version(const Call& c) { c.plhs[0] = mxCreateString(wrc_version()); }

void live_count(const Call& c) { c.plhs[0] = mxCreateDoubleScalar(static_cast<double>(live.size())); }

// The commands: the +wrc package's name, the function the messages name, the handler.
struct Command {
  const char* name;
  const char* function;
  void (*run)(const Call&);
};

const Command commands[] = {
    {"profile_load", "wrc.profile.load", profile_load},
    {"profile_points", "wrc.profile.points", profile_points},
    {"points", "points", points},
    {"write", "write", write},
    {"flange_measures", "wrc.flange_measures", flange_measures},
    {"wheelset", "wrc.wheelset", wheelset},
    {"contact", "wrc.contact", contact},
    {"wheel", "wrc.wheel", wheel},
    {"equilibrium", "wrc.equilibrium", equilibrium},
    {"rigid", "wrc.rigid", rigid},
    {"geometry_table", "wrc.geometry_table", geometry_table},
    {"wheelset_conicity", "wrc.conicity", wheelset_conicity},
    {"conicity", "wrc.conicity", conicity},
    {"trajectory", "wrc.trajectory", trajectory},
    {"trajectory_contact", "tr.contact", trajectory_contact},
    {"trajectory_wheel", "tr.wheel", trajectory_wheel},
    {"trajectory_reset", "tr.reset", trajectory_reset},
    {"free", "wrc.free", free_command},
    {"kind", "kind", kind},
    {"version", "wrc.version", version},
    {"live", "live", live_count},
};

void dispatch(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  if (wrc_abi_version() != WRC_ABI_VERSION)
    fail("wrc:abi", "libwrc has ABI version " + std::to_string(wrc_abi_version()) + ", wrc_mex was built for " +
                        std::to_string(WRC_ABI_VERSION));
  // The engine's messages about option types in MATLAB's words (struct, numeric array), on the thread that calls.
  check(wrc_set_option_dialect("matlab"));
  // A profile's warnings are raised as MATLAB warnings (collect_warnings), not printed by the library as well.
  check(wrc_set_profile_warnings_printed(0));
  if (nrhs < 1) fail("wrc:usage", "wrc_mex(command, ...): the +wrc package calls it (see docs/matlab.md)");
  const std::string name = text_of(prhs[0], "wrc_mex's command");
  for (const Command& cmd : commands)
    if (name == cmd.name) return cmd.run(Call{nlhs, plhs, nrhs - 1, prhs + 1, cmd.function});
  fail("wrc:usage", "wrc_mex: unknown command '" + name + "'");
}

}  // namespace

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  std::string id, message;
  try {
    g_warnings.clear();
    dispatch(nlhs, plhs, nrhs, prhs);
    for (const auto& [id, text] : g_warnings) mexWarnMsgIdAndTxt(id.c_str(), "%s", text.c_str());
    return;
  } catch (const Failure& f) {
    id = f.id;
    message = f.message;
  } catch (const std::bad_alloc&) {
    id = "wrc:outOfMemory";
    message = "wrc_mex: out of memory";
  } catch (const std::exception& e) {
    id = "wrc:internal";
    message = std::string("wrc_mex: internal error: ") + e.what();
  }
  // Every resource of the call is released by now; mexErrMsgIdAndTxt does not return.
  mexErrMsgIdAndTxt(id.c_str(), "%s", message.c_str());
}
