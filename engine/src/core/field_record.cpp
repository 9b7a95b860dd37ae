#include "wrc/core/field_record.hpp"

namespace wrc {

const FieldNode* FieldNode::find(std::string_view name) const {
  for (const FieldNode& c : children)
    if (c.key == name) return &c;
  return nullptr;
}

FieldRecorder::FieldRecorder(bool with_meanings) : with_meanings_(with_meanings) { open_.push_back(&root); }

void FieldRecorder::document(std::string_view key, FieldDoc doc) {
  pending_ = true;
  pending_key_ = key;
  pending_unit_ = doc.unit ? doc.unit : "";
  if (with_meanings_) pending_meaning_ = doc.meaning ? doc.meaning : "";
}

// The documentation document() gave belongs to the next field only when that field has its key.
FieldNode& FieldRecorder::add(std::string_view key, FieldNode::Kind kind) {
  FieldNode& n = open_.back()->children.emplace_back();
  n.kind = kind;
  n.key = key;
  if (pending_ && pending_key_ == key) {
    n.documented = true;
    n.unit = std::move(pending_unit_);
    n.meaning = std::move(pending_meaning_);
  }
  pending_ = false;
  pending_unit_.clear();
  pending_meaning_.clear();
  return n;
}

void FieldRecorder::number(std::string_view key, double v) { add(key, FieldNode::Kind::number).number = v; }

void FieldRecorder::integer(std::string_view key, long long v) { add(key, FieldNode::Kind::integer).integer = v; }

void FieldRecorder::boolean(std::string_view key, bool v) { add(key, FieldNode::Kind::boolean).integer = v ? 1 : 0; }

void FieldRecorder::string(std::string_view key, std::string_view v) { add(key, FieldNode::Kind::string).text = v; }

void FieldRecorder::numbers(std::string_view key, const double* v, std::size_t n) {
  add(key, FieldNode::Kind::numbers).values.assign(v, v + n);
}

void FieldRecorder::integers(std::string_view key, const long long* v, std::size_t n) {
  add(key, FieldNode::Kind::integers).integers.assign(v, v + n);
}

void FieldRecorder::grid(std::string_view key, const double* v, int nx, int ny) {
  FieldNode& g = add(key, FieldNode::Kind::grid);
  g.values.assign(v, v + static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));
  g.nx = nx;
  g.ny = ny;
}

void FieldRecorder::begin(std::string_view key) { open_.push_back(&add(key, FieldNode::Kind::table)); }

void FieldRecorder::begin_list(std::string_view key, std::size_t n) {
  FieldNode& l = add(key, FieldNode::Kind::list);
  l.count = n;
  l.children.reserve(n);
  open_.push_back(&l);
}

void FieldRecorder::item() { open_.push_back(&add("", FieldNode::Kind::table)); }

void FieldRecorder::end() {
  if (open_.size() > 1) open_.pop_back();
}

void FieldRecorder::object_type(std::string_view name) { open_.back()->object_type = name; }

}  // namespace wrc
