// DocSink (wrc/core/field_reference.hpp): the paths, kinds and documentation of described fields.
#include "wrc/core/field_reference.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace wrc {

namespace {

// The two wheels' tables are described alike: one pattern for both.
std::string pattern_key(std::string_view key) {
  return key == "left" || key == "right" ? "<side>" : std::string(key);
}

// Text for a Markdown table cell.
std::string cell(const std::string& text) {
  std::string out;
  for (char ch : text) {
    if (ch == '|') out += "\\|";
    else if (ch == '<') out += "&lt;";
    else if (ch == '>') out += "&gt;";
    else out += ch;
  }
  return out;
}

bool numeric(std::string_view kind) {
  return kind == "number" || kind == "integer" || kind == "numbers" || kind == "integers" || kind == "grid";
}

}  // namespace

void DocSink::check(const FieldEntry& e, bool documented, const FieldEntry* seen) {
  std::vector<std::string> found;
  if (!documented) found.push_back(fmt::format("{}: written without a FieldDoc (unit and meaning)", e.c));
  else if (e.meaning.empty()) found.push_back(fmt::format("{}: no meaning", e.c));
  if (documented && numeric(e.kind) && e.unit.empty())
    found.push_back(fmt::format("{}: a {} without a unit (\"-\" for a pure number, an index or a count)", e.c, e.kind));
  if ((e.kind == "string" || e.kind == "boolean" || e.kind == "list") && !e.unit.empty())
    found.push_back(fmt::format("{}: a {} with the unit \"{}\" (text, flags and lists have none)", e.c, e.kind, e.unit));
  if (documented && seen && (seen->kind != e.kind || seen->unit != e.unit || seen->meaning != e.meaning))
    found.push_back(fmt::format("{}: documented two ways: {} [{}] \"{}\" and {} [{}] \"{}\"", e.c, seen->kind,
                                seen->unit, seen->meaning, e.kind, e.unit, e.meaning));
  for (std::string& f : found)  // each once, however often the field is written
    if (std::find(problems_.begin(), problems_.end(), f) == problems_.end()) problems_.push_back(std::move(f));
}

void DocSink::restart() {
  next_ = 0;
  frames_.clear();
  has_pending_ = false;
}

void DocSink::document(std::string_view key, FieldDoc doc) {
  pending_key_ = std::string(key);
  pending_ = doc;
  has_pending_ = true;
}

void DocSink::add(std::string_view key, const char* kind) {
  const std::string k = pattern_key(key);
  FieldEntry e;
  e.lua = frames_.empty() ? k : frames_.back().lua + "." + k;
  e.c = (frames_.empty() ? "" : frames_.back().c) + k;
  e.kind = kind;
  const bool documented = has_pending_ && pending_key_ == key;
  if (documented) {
    e.unit = pending_.unit ? pending_.unit : "";
    e.meaning = pending_.meaning ? pending_.meaning : "";
  }
  has_pending_ = false;
  const auto same = std::find_if(entries_.begin(), entries_.end(), [&](const FieldEntry& x) { return x.c == e.c; });
  check(e, documented, same == entries_.end() ? nullptr : &*same);
  if (same == entries_.end()) {
    entries_.insert(entries_.begin() + static_cast<std::ptrdiff_t>(next_), e);
    ++next_;
  } else {
    next_ = static_cast<std::size_t>(same - entries_.begin()) + 1;
  }
}

void DocSink::begin(std::string_view key) {
  add(key, "table");
  const FieldEntry& e = entries_[next_ - 1];
  frames_.push_back({e.lua, e.c + ".", false});
}

void DocSink::begin_list(std::string_view key, std::size_t) {
  add(key, "list");
  const FieldEntry& e = entries_[next_ - 1];
  frames_.push_back({e.lua, e.c + ".", true});
}

void DocSink::item() {
  const Frame list = frames_.back();
  frames_.push_back({list.lua + "[N]", list.c + "N.", false});
}

void DocSink::end() { frames_.pop_back(); }

std::string field_table(const std::vector<FieldEntry>& entries) {
  std::string out = "| Lua path | C path | type | unit | meaning |\n| --- | --- | --- | --- | --- |\n";
  for (const FieldEntry& e : entries)
    out += fmt::format("| `{}` | `{}` | {} | {} | {} |\n", e.lua, e.c, e.kind, cell(e.unit), cell(e.meaning));
  return out;
}

}  // namespace wrc
