#include "python/field_tree.hpp"

namespace wrc::python {

const FieldNode* FieldNode::find(std::string_view name) const {
  for (const FieldNode& c : children)
    if (c.key == name) return &c;
  return nullptr;
}

FieldTree::FieldTree() { open_.push_back(&root); }

void FieldTree::document(std::string_view key, FieldDoc doc) {
  pending_key_ = key;
  pending_unit_ = doc.unit ? doc.unit : "";
}

FieldNode& FieldTree::add(std::string_view key, FieldNode::Kind kind) {
  FieldNode& n = open_.back()->children.emplace_back();
  n.kind = kind;
  n.key = key;
  if (pending_key_ == key) n.unit = std::move(pending_unit_);
  pending_key_.clear();
  pending_unit_.clear();
  return n;
}

void FieldTree::number(std::string_view key, double v) { add(key, FieldNode::Kind::number).number = v; }

void FieldTree::integer(std::string_view key, long long v) { add(key, FieldNode::Kind::integer).integer = v; }

void FieldTree::boolean(std::string_view key, bool v) { add(key, FieldNode::Kind::boolean).integer = v ? 1 : 0; }

void FieldTree::string(std::string_view key, std::string_view v) { add(key, FieldNode::Kind::string).text = v; }

void FieldTree::numbers(std::string_view key, const double* v, std::size_t n) {
  add(key, FieldNode::Kind::numbers).values.assign(v, v + n);
}

void FieldTree::integers(std::string_view key, const long long* v, std::size_t n) {
  add(key, FieldNode::Kind::integers).integers.assign(v, v + n);
}

void FieldTree::grid(std::string_view key, const double* v, int nx, int ny) {
  FieldNode& g = add(key, FieldNode::Kind::grid);
  g.values.assign(v, v + static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));
  g.nx = nx;
  g.ny = ny;
}

void FieldTree::begin(std::string_view key) { open_.push_back(&add(key, FieldNode::Kind::table)); }

void FieldTree::begin_list(std::string_view key, std::size_t n) {
  FieldNode& l = add(key, FieldNode::Kind::list);
  l.children.reserve(n);
  open_.push_back(&l);
}

void FieldTree::item() { open_.push_back(&add("", FieldNode::Kind::table)); }

void FieldTree::end() {
  if (open_.size() > 1) open_.pop_back();
}

}  // namespace wrc::python
