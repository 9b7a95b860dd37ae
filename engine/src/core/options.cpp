#include "wrc/core/options.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <unordered_map>

namespace wrc {

OptionValue OptionValue::of(double v) {
  OptionValue o;
  o.type = Type::number;
  o.number = v;
  return o;
}

OptionValue OptionValue::of(bool v) {
  OptionValue o;
  o.type = Type::boolean;
  o.boolean = v;
  return o;
}

OptionValue OptionValue::of(std::string v) {
  OptionValue o;
  o.type = Type::string;
  o.string = std::move(v);
  return o;
}

OptionValue OptionValue::of(std::vector<OptionValue> v) {
  OptionValue o;
  o.type = Type::array;
  o.array = std::move(v);
  return o;
}

OptionValue OptionValue::of(OptionTable t) {
  OptionValue o;
  o.type = Type::table;
  o.table = std::make_shared<const OptionTable>(std::move(t));
  return o;
}

OptionValue OptionValue::of_object(std::shared_ptr<const void> p, std::string type) {
  OptionValue o;
  o.type = Type::object;
  o.object = std::move(p);
  o.string = std::move(type);
  return o;
}

const OptionWords& option_words(OptionDialect dialect) {
  static const OptionWords lua{"boolean", "string", "array", "table",
                               "a table", "an array of numbers", "an array of strings", "{from =, to =, step =}"};
  static const OptionWords c{"boolean", "string", "list", "table (dotted keys)",
                             "a table (dotted keys: key.name=value)", "a list of numbers (a,b,c)", "a list of strings",
                             "key.from= key.to= key.step="};
  static const OptionWords python{"bool", "str", "list", "dict",
                                  "a dict", "a list or 1-D numpy array of numbers", "a list of str",
                                  "dict(from=, to=, step=)"};
  static const OptionWords matlab{"logical", "char array", "numeric array", "struct",
                                  "a struct", "a numeric array", "a cell array of char arrays",
                                  "struct('from', a, 'to', b, 'step', h)"};
  switch (dialect) {
    case OptionDialect::lua: return lua;
    case OptionDialect::c: return c;
    case OptionDialect::python: return python;
    case OptionDialect::matlab: return matlab;
  }
  return lua;
}

const char* OptionValue::type_name(OptionDialect dialect) const {
  const OptionWords& w = option_words(dialect);
  switch (type) {
    case Type::number: return "number";
    case Type::boolean: return w.boolean;
    case Type::string: return w.string;
    case Type::array: return w.array;
    case Type::table: return w.table;
    case Type::object: return string.c_str();
  }
  return "?";
}

const OptionValue* OptionTable::find(std::string_view key) const {
  for (const auto& [k, v] : entries)
    if (k == key) return &v;
  return nullptr;
}

OptionTable& OptionTable::set(std::string key, OptionValue v) {
  for (auto& [k, old] : entries)
    if (k == key) {
      old = std::move(v);
      return *this;
    }
  entries.emplace_back(std::move(key), std::move(v));
  return *this;
}

namespace {

// Lua has one kind of table: {} is an empty array as much as an empty table, so a reader that wants an array takes it
// as one (and says that it is empty, where "must be an array of numbers, got table" named the wrong fault).
bool empty_lua_table(const OptionValue& v) {
  return v.type == OptionValue::Type::table && v.table && v.table->empty() && v.table->dialect == OptionDialect::lua;
}

bool parse_double(std::string_view s, double& out) {
  if (s.empty()) return false;
  const std::string t(s);
  char* end = nullptr;
  out = std::strtod(t.c_str(), &end);
  return end == t.c_str() + t.size();
}

OptionValue parse_scalar_or_list(std::string_view text) {
  double d = 0;
  if (text == "true" || text == "false") return OptionValue::of(text == "true");
  if (parse_double(text, d)) return OptionValue::of(d);
  if (text.find(',') != std::string_view::npos) {
    std::vector<OptionValue> list;
    std::size_t start = 0;
    bool numeric = true;
    while (numeric && start <= text.size()) {
      const std::size_t comma = std::min(text.find(',', start), text.size());
      numeric = parse_double(text.substr(start, comma - start), d);
      list.push_back(OptionValue::of(d));
      start = comma + 1;
    }
    if (numeric) return OptionValue::of(std::move(list));
  }
  return OptionValue::of(std::string(text));
}

// A table while the text is parsed: its entries in the order given, found by key in constant time; a sub-table
// stays mutable until the end (OptionValue's tables are shared and immutable: copying one per key made the parse
// quadratic).
struct TableBuilder {
  std::vector<std::string> keys;
  std::vector<OptionValue> values;                    // the entry's value (unused for a sub-table)
  std::vector<std::unique_ptr<TableBuilder>> tables;  // the entry's sub-table, or null for a value
  std::unordered_map<std::string, std::size_t> index; // key -> entry

  // The entry `key` and whether it was there before; a new entry is a sub-table when `table`.
  std::pair<std::size_t, bool> entry(std::string_view key, bool table) {
    const auto [it, added] = index.emplace(std::string(key), keys.size());
    if (added) {
      keys.emplace_back(key);
      values.emplace_back();
      tables.push_back(table ? std::make_unique<TableBuilder>() : nullptr);
    }
    return {it->second, !added};
  }

  // The finished table (recursion bounded by kMaxOptionDepth).
  OptionTable finish(OptionDialect dialect) {
    OptionTable t;
    t.dialect = dialect;
    t.entries.reserve(keys.size());
    for (std::size_t i = 0; i < keys.size(); ++i)
      t.entries.emplace_back(std::move(keys[i]),
                             tables[i] ? OptionValue::of(tables[i]->finish(dialect)) : std::move(values[i]));
    return t;
  }
};

// Sets a dotted key ("shift.y") in nested tables: a name is a value or a table, not both, and a key is given once.
void set_path(TableBuilder& root, std::string_view key, OptionValue v, std::string_view context) {
  if (key.size() > kMaxOptionKeyLength)
    fail("{}: the key '{:.40}...' is {} characters long (at most {})", context, key, key.size(), kMaxOptionKeyLength);
  TableBuilder* t = &root;
  for (std::size_t start = 0, level = 1;; ++level) {
    const std::size_t dot = std::min(key.find('.', start), key.size());
    const bool last = dot == key.size();
    if (dot == start) fail("{}: the key '{}' has an empty name between its dots", context, key);
    if (level > kMaxOptionDepth) fail("{}: the key '{:.40}...' nests more than {} levels", context, key, kMaxOptionDepth);
    const auto [i, existed] = t->entry(key.substr(start, dot - start), !last);
    if (existed && last && !t->tables[i]) fail("{}: '{}' is given twice", context, key);
    if (existed && (last || !t->tables[i])) fail("{}: '{}' is both a value and a table", context, key.substr(0, dot));
    if (last) {
      t->values[i] = std::move(v);
      return;
    }
    t = t->tables[i].get();
    start = dot + 1;
  }
}

}  // namespace

OptionTable parse_option_text(std::string_view text, std::string_view context, OptionDialect dialect) {
  if (text.size() > kMaxOptionTextLength)
    fail("{}: the option text is {} bytes long (at most {})", context, text.size(), kMaxOptionTextLength);
  TableBuilder root;
  std::size_t i = 0;
  auto is_sep = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ';'; };
  while (i < text.size()) {
    while (i < text.size() && is_sep(text[i])) ++i;
    if (i >= text.size()) break;
    std::size_t j = i;
    while (j < text.size() && !is_sep(text[j])) ++j;
    const std::string_view pair = text.substr(i, j - i);
    const std::size_t eq = pair.find('=');
    if (eq == std::string_view::npos || eq == 0) fail("{}: '{:.80}' is not a key=value pair", context, pair);
    set_path(root, pair.substr(0, eq), parse_scalar_or_list(pair.substr(eq + 1)), context);
    i = j;
  }
  return root.finish(dialect);
}

std::string closest_name(std::string_view key, const std::vector<std::string>& known) {
  auto distance = [](std::string_view a, std::string_view b) {  // Levenshtein, one row
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
      std::size_t diag = row[0];
      row[0] = i;
      for (std::size_t j = 1; j <= b.size(); ++j) {
        const std::size_t up = row[j];
        row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
        diag = up;
      }
    }
    return row[b.size()];
  };
  // The same letters in another case first ('q' for 'Q', 'FZ' for 'Fz'): one edit away from 'y' too, but the typo.
  const auto lower = [](std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
  };
  for (const auto& k : known)
    if (lower(k) == lower(key)) return k;
  std::string best;
  std::size_t best_d = std::max<std::size_t>(2, key.size() / 3) + 1;  // more edits than that: not a typo
  for (const auto& k : known) {
    const std::size_t d = distance(key, k);
    if (d >= std::max(key.size(), k.size())) continue;  // every letter changed ('ab' and 'mu'): no likeness at all
    if (d < best_d) {
      best_d = d;
      best = k;
    }
  }
  return best;
}

OptionReader::OptionReader(const OptionTable& table, std::string context)
    : table_(table), context_(std::move(context)), dialect_(table.dialect) {}

OptionReader OptionReader::nested(const OptionTable& table, std::string context) const {
  OptionReader r(table, std::move(context));
  r.dialect_ = dialect_;
  return r;
}

OptionReader OptionReader::documenting(std::string context, std::vector<OptionInfo>& out) {
  static const OptionTable nothing;
  OptionReader r(nothing, std::move(context));
  r.doc_ = &out;
  return r;
}

namespace {

std::string fallback_text(double v) { return fmt::format("{}", v); }
std::string fallback_text(bool v) { return v ? "true" : "false"; }
std::string fallback_text(const std::string& v) { return fmt::format("\"{}\"", v); }

std::vector<std::string> choice_list(std::initializer_list<std::string_view> choices) {
  return {choices.begin(), choices.end()};
}

}  // namespace

void OptionReader::note(std::string_view key, std::string_view type, OptionDoc doc, std::string fallback,
                        bool required, std::vector<std::string> choices) {
  const std::string full = prefix_ + std::string(key);
  auto it = std::find_if(doc_->begin(), doc_->end(), [&](const OptionInfo& i) { return i.key == full; });
  if (it == doc_->end()) {
    doc_->push_back(OptionInfo{full, std::string(type), "", "", "", false, {}});
    it = doc_->end() - 1;
  }
  auto fill = [](std::string& slot, std::string_view v) {
    if (slot.empty() && !v.empty()) slot = std::string(v);
  };
  fill(it->unit, doc.unit ? doc.unit : "");
  fill(it->help, doc.help ? doc.help : "");
  fill(it->fallback, fallback);
  it->required = it->required || required;
  if (it->choices.empty()) it->choices = std::move(choices);
}

const OptionValue* OptionReader::value(std::string_view key) {
  if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.emplace_back(key);
  return table_.find(key);
}

const OptionValue* OptionReader::value(std::string_view key, std::string_view type, OptionDoc doc, std::string fallback) {
  if (doc_) note(key, type, doc, std::move(fallback));
  return value(key);
}

bool OptionReader::has(std::string_view key) { return value(key) != nullptr; }

void OptionReader::allow(std::initializer_list<std::string_view> keys) {
  for (auto k : keys) value(k);
}

void OptionReader::type_error(std::string_view key, const OptionValue& v, std::string_view expected,
                              std::string_view help) const {
  fail("{}: '{}' must be {}, got {}{}", context_, key, expected, type_name(v),
       help.empty() ? std::string() : fmt::format(" ({}: {})", key, help));
}

std::optional<double> OptionReader::number(std::string_view key, OptionDoc doc) {
  if (doc_) note(key, "number", doc);
  const OptionValue* v = value(key);
  if (!v) return std::nullopt;
  if (v->type != OptionValue::Type::number) type_error(key, *v, "a number");
  if (!std::isfinite(v->number)) fail("{}: '{}' must be finite, got {}", context_, key, v->number);
  return v->number;
}

double OptionReader::number(std::string_view key, OptionDoc doc, double fallback) {
  if (doc_) note(key, "number", doc, fallback_text(fallback));
  return number(key, doc).value_or(fallback);
}

double OptionReader::need_number(std::string_view key, OptionDoc doc) {
  if (doc_) {
    note(key, "number", doc, {}, true);
    return 0;
  }
  const auto v = number(key, doc);
  if (!v) fail("{}: '{}' is required (a number)", context_, key);
  return *v;
}

std::optional<int> OptionReader::integer(std::string_view key, int lo, int hi, OptionDoc doc) {
  if (doc_) note(key, "integer", doc);
  const OptionValue* raw = value(key);
  if (!raw) return std::nullopt;
  const double v = *number(key, doc);
  if (v != std::floor(v) || v < lo || v > hi)
    fail("{}: '{}' must be a whole number in {}..{}, got {}", context_, key, lo, hi, v);
  return static_cast<int>(v);
}

int OptionReader::integer(std::string_view key, int lo, int hi, OptionDoc doc, int fallback) {
  if (doc_) note(key, "integer", doc, std::to_string(fallback));
  return integer(key, lo, hi, doc).value_or(fallback);
}

std::optional<bool> OptionReader::boolean(std::string_view key, OptionDoc doc) {
  if (doc_) note(key, "boolean", doc);
  const OptionValue* v = value(key);
  if (!v) return std::nullopt;
  if (v->type != OptionValue::Type::boolean) type_error(key, *v, "a boolean");
  return v->boolean;
}

bool OptionReader::boolean(std::string_view key, OptionDoc doc, bool fallback) {
  if (doc_) note(key, "boolean", doc, fallback_text(fallback));
  return boolean(key, doc).value_or(fallback);
}

std::optional<std::string> OptionReader::string(std::string_view key, OptionDoc doc) {
  if (doc_) note(key, "string", doc);
  const OptionValue* v = value(key);
  if (!v) return std::nullopt;
  if (v->type != OptionValue::Type::string) type_error(key, *v, "a string");
  return v->string;
}

std::string OptionReader::string(std::string_view key, OptionDoc doc, std::string fallback) {
  if (doc_) note(key, "string", doc, fallback_text(fallback));
  auto v = string(key, doc);
  return v ? std::move(*v) : std::move(fallback);
}

std::optional<std::string> OptionReader::choice(std::string_view key, std::initializer_list<std::string_view> choices,
                                                OptionDoc doc) {
  if (doc_) note(key, "choice", doc, {}, false, choice_list(choices));
  auto s = string(key, doc);
  if (!s) return s;
  std::string list;
  for (auto c : choices) {
    if (*s == c) return s;
    list += (list.empty() ? "\"" : ", \"") + std::string(c) + "\"";
  }
  fail("{}: '{}' must be one of {}, got \"{}\"", context_, key, list, *s);
}

std::string OptionReader::choice(std::string_view key, std::initializer_list<std::string_view> choices, OptionDoc doc,
                                 std::string fallback) {
  if (doc_) note(key, "choice", doc, fallback_text(fallback), false, choice_list(choices));
  auto v = choice(key, choices, doc);
  return v ? std::move(*v) : std::move(fallback);
}

std::optional<std::vector<double>> OptionReader::numbers(std::string_view key, bool finite) {
  return numbers(key, OptionDoc{}, finite);
}

std::optional<std::vector<double>> OptionReader::numbers(std::string_view key, OptionDoc doc, bool finite) {
  if (doc_) note(key, "numbers", doc);
  const OptionValue* v = value(key);
  if (!v) return std::nullopt;
  if (v->type == OptionValue::Type::number && !finite) return std::vector<double>{v->number};
  if (v->type == OptionValue::Type::number) return std::vector<double>{*number(key)};
  if (empty_lua_table(*v)) return std::vector<double>{};
  if (v->type != OptionValue::Type::array) type_error(key, *v, words().numbers);
  std::vector<double> out;
  out.reserve(v->array.size());
  for (std::size_t i = 0; i < v->array.size(); ++i) {
    const OptionValue& e = v->array[i];
    const auto at = [&] { return value_at(i, fmt::format("'{}'", key)); };
    if (e.type != OptionValue::Type::number) fail("{}: {} must be a number, got {}", context_, at(), type_name(e));
    if (finite && !std::isfinite(e.number)) fail("{}: {} must be finite, got {}", context_, at(), e.number);
    out.push_back(e.number);
  }
  return out;
}

std::optional<std::vector<std::string>> OptionReader::strings(std::string_view key, OptionDoc doc) {
  if (doc_) note(key, "strings", doc);
  const OptionValue* v = value(key);
  if (!v) return std::nullopt;
  if (empty_lua_table(*v)) return std::vector<std::string>{};
  if (v->type != OptionValue::Type::array) type_error(key, *v, words().strings);
  std::vector<std::string> out;
  for (std::size_t i = 0; i < v->array.size(); ++i) {
    if (v->array[i].type != OptionValue::Type::string)
      fail("{}: {} must be a string, got {}", context_, value_at(i, fmt::format("'{}'", key)), type_name(v->array[i]));
    out.push_back(v->array[i].string);
  }
  return out;
}

std::optional<std::vector<double>> OptionReader::number_list(std::string_view key, std::size_t max_count) {
  return number_list(key, OptionDoc{}, max_count);
}

std::optional<std::vector<double>> OptionReader::number_list(std::string_view key, OptionDoc doc, std::size_t max_count) {
  if (doc_) note(key, "list", doc);
  const OptionValue* v = value(key);
  if (!v) return std::nullopt;
  std::vector<double> out;
  if (empty_lua_table(*v)) {
    // out stays empty: named so below
  } else if (v->type == OptionValue::Type::table) {
    OptionReader r = nested(*v->table, fmt::format("{}: '{}' ({})", context_, key, words().range));
    r.allow({"from", "to", "step"});
    r.finish();  // a misspelt key first ('too' given, so 'to' is missing)
    const double from = r.need_number("from"), to = r.need_number("to"), step = r.need_number("step");
    if (!(step > 0)) fail("{}: '{}.step' must be > 0, got {}", context_, key, step);
    const double n = std::floor(std::abs(to - from) / step + 1e-9);
    if (n + 1 > static_cast<double>(max_count)) fail("{}: '{}' asks for {} values (at most {})", context_, key, n + 1, max_count);
    const double dir = to >= from ? 1.0 : -1.0;
    for (int i = 0; i <= static_cast<int>(n); ++i) out.push_back(from + dir * step * i);
  } else if (v->type == OptionValue::Type::number || v->type == OptionValue::Type::array) {
    out = *numbers(key);
    if (out.size() > max_count) fail("{}: '{}' has {} values (at most {})", context_, key, out.size(), max_count);
  } else {
    type_error(key, *v, fmt::format("a number, {} or {}", words().numbers, words().range));
  }
  if (out.empty()) fail("{}: '{}' is empty", context_, key);
  return out;
}

std::optional<OptionReader> OptionReader::table(std::string_view key, OptionDoc doc) {
  if (doc_) {
    note(key, "table", doc);
    OptionReader sub = documenting(fmt::format("{}: '{}'", context_, key), *doc_);
    sub.prefix_ = prefix_ + std::string(key) + ".";
    return sub;
  }
  const OptionValue* v = value(key);
  if (!v) return std::nullopt;
  // The help shows the table's shape: {y =, mu =} for a list of pairs.
  if (v->type != OptionValue::Type::table) type_error(key, *v, words().a_table, doc.help);
  return nested(*v->table, fmt::format("{}: '{}'", context_, key));
}

std::shared_ptr<const void> OptionReader::object(std::string_view key, std::string_view type, OptionDoc doc) {
  if (doc_) note(key, type, doc);
  const OptionValue* v = value(key);
  if (!v) return nullptr;
  if (v->type != OptionValue::Type::object || v->string != type) type_error(key, *v, fmt::format("a {}", type));
  return v->object;
}

std::vector<const std::pair<std::string, OptionValue>*> OptionReader::rest() const {
  std::vector<const std::pair<std::string, OptionValue>*> out;
  for (const auto& e : table_.entries)
    if (std::find(known_.begin(), known_.end(), e.first) == known_.end()) out.push_back(&e);
  return out;
}

void OptionReader::finish() const {
  if (doc_) return;
  for (const auto& [key, v] : table_.entries) {
    if (std::find(known_.begin(), known_.end(), key) != known_.end()) continue;
    std::string list;
    for (const auto& k : known_) list += (list.empty() ? "" : ", ") + k;
    const std::string near = closest_name(key, known_);
    fail("{}: unknown key '{}' ({}expected one of: {})", context_, key,
         near.empty() ? "" : fmt::format("did you mean '{}'? ", near), list);
  }
}

}  // namespace wrc
