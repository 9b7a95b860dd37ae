#include "wrc/core/field_record.hpp"

#include <algorithm>
#include <cstring>
#include <type_traits>

namespace wrc {

const FieldNode* FieldNode::find(std::string_view name) const {
  for (const FieldNode& c : children())
    if (c.key == name) return &c;
  return nullptr;
}

const FieldNode* FieldNode::child(std::size_t k) const {
  if (k >= fields) return nullptr;
  auto it = children().begin();
  while (k-- > 0) ++it;
  return &*it;
}

FieldRecord::FieldRecord() { nodes_.emplace_back(); }

FieldRecord::FieldRecord(FieldRecord&& other) noexcept
    : nodes_(std::move(other.nodes_)),
      blocks_(std::move(other.blocks_)),
      large_(std::move(other.large_)),
      free_(std::exchange(other.free_, nullptr)),
      left_(std::exchange(other.left_, 0)),
      size_(std::exchange(other.size_, 0)),
      used_(std::exchange(other.used_, 0)) {}

FieldRecord& FieldRecord::operator=(FieldRecord&& other) noexcept {
  nodes_ = std::move(other.nodes_);
  blocks_ = std::move(other.blocks_);
  large_ = std::move(other.large_);
  free_ = std::exchange(other.free_, nullptr);
  left_ = std::exchange(other.left_, 0);
  size_ = std::exchange(other.size_, 0);
  used_ = std::exchange(other.used_, 0);
  return *this;
}

void FieldRecord::clear() {
  if (nodes_.empty()) nodes_.emplace_back();  // a moved-from record
  nodes_.resize(1);
  nodes_.front() = FieldNode();
  large_.clear();
  constexpr std::size_t kKept = std::size_t{64} << 20;
  const bool one_fits = blocks_.size() == 1 && size_ >= used_;
  if (!one_fits) {
    blocks_.clear();
    size_ = used_ <= kKept ? used_ : 0;
    if (size_ > 0) blocks_.push_back(std::make_unique_for_overwrite<std::byte[]>(size_));
  }
  free_ = blocks_.empty() ? nullptr : blocks_.front().get();
  left_ = blocks_.empty() ? 0 : size_;
  used_ = 0;
}

std::size_t FieldRecord::bytes() const {
  std::size_t n = nodes_.size() * sizeof(FieldNode) + used_;
  for (const std::vector<double>& v : large_) n += v.capacity() * sizeof(double);
  return n;
}

// Blocks grow from 1 KiB to 64 KiB (a result of a few fields stays small, a wheel's ~4000 fields take few blocks); an
// array larger than a quarter of that that does not fit the current block gets a block of its own, the current one
// kept for the small copies.
void* FieldRecord::allocate(std::size_t bytes) {
  constexpr std::size_t kLargest = std::size_t{64} << 10;
  bytes = (bytes + 7) & ~std::size_t{7};
  used_ += bytes;
  if (bytes > left_ && bytes > kLargest / 4) {
    blocks_.push_back(std::make_unique_for_overwrite<std::byte[]>(bytes));
    return blocks_.back().get();
  }
  if (bytes > left_) {
    size_ = std::max(bytes, std::min(kLargest, std::size_t{1024} << std::min<std::size_t>(blocks_.size(), 6)));
    blocks_.push_back(std::make_unique_for_overwrite<std::byte[]>(size_));
    free_ = blocks_.back().get();
    left_ = size_;
  }
  void* p = free_;
  free_ += bytes;
  left_ -= bytes;
  return p;
}

std::string_view FieldRecord::copy(std::string_view s) {
  if (s.empty()) return {};
  char* p = static_cast<char*>(allocate(s.size()));
  std::memcpy(p, s.data(), s.size());
  return {p, s.size()};
}

std::vector<double> FieldRecord::take_values(const FieldNode& node) {
  for (std::vector<double>& v : large_)
    if (!v.empty() && v.data() == node.values.data()) return std::move(v);
  return {node.values.begin(), node.values.end()};
}

template <class T>
std::span<const T> FieldRecord::copy(const T* v, std::size_t n) {
  if (n == 0) return {};
  constexpr std::size_t kLarge = std::size_t{16} << 10;  // bytes: an array this large has a vector of its own
  if constexpr (std::is_same_v<T, double>) {
    if (n * sizeof(T) > kLarge) {
      const std::vector<double>& own = large_.emplace_back(v, v + n);
      return {own.data(), n};
    }
  }
  T* p = static_cast<T*>(allocate(n * sizeof(T)));
  std::memcpy(p, v, n * sizeof(T));
  return {p, n};
}

FieldRecord& thread_record_storage() {
  thread_local FieldRecord storage;
  return storage;
}

FieldRecorder::FieldRecorder(bool with_meanings) : open_{0}, with_meanings_(with_meanings) {}

FieldRecorder::FieldRecorder(FieldRecord&& storage) : record_(std::move(storage)), open_{0}, with_meanings_(false) {
  record_.clear();
}

FieldRecord FieldRecorder::take() {
  std::vector<FieldNode>& nodes = record_.nodes_;
  for (std::size_t i : open_) nodes[i].below = nodes.size() - i - 1;
  open_.assign(1, 0);
  pending_ = false;
  return std::exchange(record_, FieldRecord());
}

void FieldRecorder::document(std::string_view key, FieldDoc doc) {
  pending_ = true;
  pending_key_ = key;
  pending_doc_ = doc;
}

// The documentation document() gave belongs to the next field only when that field has its key.
FieldNode& FieldRecorder::add(std::string_view key, FieldNode::Kind kind) {
  ++record_.nodes_[open_.back()].fields;
  FieldNode& n = record_.nodes_.emplace_back();
  n.kind = kind;
  n.key = record_.copy(key);
  if (pending_ && pending_key_ == key) {
    n.documented = true;
    if (pending_doc_.unit) n.unit = record_.copy(pending_doc_.unit);
    if (with_meanings_ && pending_doc_.meaning) n.meaning = record_.copy(pending_doc_.meaning);
  }
  pending_ = false;
  return n;
}

void FieldRecorder::number(std::string_view key, double v) { add(key, FieldNode::Kind::number).number = v; }

void FieldRecorder::integer(std::string_view key, long long v) { add(key, FieldNode::Kind::integer).integer = v; }

void FieldRecorder::boolean(std::string_view key, bool v) { add(key, FieldNode::Kind::boolean).integer = v ? 1 : 0; }

void FieldRecorder::string(std::string_view key, std::string_view v) {
  FieldNode& s = add(key, FieldNode::Kind::string);
  s.text = record_.copy(v);
}

void FieldRecorder::numbers(std::string_view key, const double* v, std::size_t n) {
  FieldNode& a = add(key, FieldNode::Kind::numbers);
  a.values = record_.copy(v, n);
}

void FieldRecorder::integers(std::string_view key, const long long* v, std::size_t n) {
  FieldNode& a = add(key, FieldNode::Kind::integers);
  a.integers = record_.copy(v, n);
}

void FieldRecorder::grid(std::string_view key, const double* v, int nx, int ny) {
  FieldNode& g = add(key, FieldNode::Kind::grid);
  g.values = record_.copy(v, static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));
  g.nx = nx;
  g.ny = ny;
}

void FieldRecorder::begin(std::string_view key) {
  add(key, FieldNode::Kind::table);
  open_.push_back(record_.nodes_.size() - 1);
}

void FieldRecorder::begin_list(std::string_view key, std::size_t n) {
  add(key, FieldNode::Kind::list).count = n;
  open_.push_back(record_.nodes_.size() - 1);
}

void FieldRecorder::item() {
  add("", FieldNode::Kind::table);
  open_.push_back(record_.nodes_.size() - 1);
}

void FieldRecorder::end() {
  if (open_.size() <= 1) return;
  std::vector<FieldNode>& nodes = record_.nodes_;
  nodes[open_.back()].below = nodes.size() - open_.back() - 1;
  open_.pop_back();
}

void FieldRecorder::object_type(std::string_view name) {
  record_.nodes_[open_.back()].object_type = record_.copy(name);
}

}  // namespace wrc
