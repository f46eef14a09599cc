// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The parsed content of a model file: a compact read-only tree of scalars, lists and maps,
// each node with its 1-based line and column. Built event by event from YAML or JSON (see
// yaml_support.hpp), so the limits on size, nesting and aliases are enforced while reading;
// a node costs about 24 bytes plus its text. No parser type appears here.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace kinestat::io {

class ModelTree;
class TreeNode;
template <typename Value>
class TreeRange;
struct TreeEntry;

/// A handle to one node of a ModelTree (cheap to copy; valid while the tree lives). A default
/// constructed TreeNode is "undefined": the result of looking up a key that is not there.
class TreeNode {
 public:
  enum class Kind : std::uint8_t { undefined, null, scalar, sequence, map };

  TreeNode() = default;

  Kind kind() const;
  bool defined() const { return kind() != Kind::undefined; }
  bool is_null() const { return kind() == Kind::null; }
  bool is_scalar() const { return kind() == Kind::scalar; }
  bool is_sequence() const { return kind() == Kind::sequence; }
  bool is_map() const { return kind() == Kind::map; }

  /// The text of a scalar (after YAML unescaping); empty for other kinds.
  std::string_view scalar() const;
  /// Items of a sequence, entries of a map, 0 otherwise.
  std::size_t size() const;
  /// Item `i` of a sequence (undefined if out of range or not a sequence).
  TreeNode operator[](std::size_t i) const;
  /// The value stored under the scalar key `key` of a map (undefined if absent).
  TreeNode operator[](std::string_view key) const;
  /// Key and value of entry `i` of a map.
  TreeNode key(std::size_t i) const;
  TreeNode value(std::size_t i) const;

  /// 1-based line and column where the node starts; 0 for an undefined node.
  int line() const;
  int column() const;

  /// `for (TreeNode item : node.items())` over a sequence (empty for other kinds).
  TreeRange<TreeNode> items() const;
  /// `for (auto [key, value] : node.entries())` over a map (empty for other kinds).
  TreeRange<TreeEntry> entries() const;

 private:
  friend class ModelTree;
  TreeNode(const ModelTree* tree, std::uint32_t index) : tree_(tree), index_(index) {}
  const ModelTree* tree_ = nullptr;
  std::uint32_t index_ = 0;
};

/// A map entry, as iterated by TreeNode::entries().
struct TreeEntry {
  TreeNode first;   ///< the key
  TreeNode second;  ///< the value
};

/// Iterates the items of a sequence (Value = TreeNode) or the entries of a map (TreeEntry).
template <typename Value>
class TreeRange {
 public:
  class iterator {
   public:
    iterator(const TreeNode* owner, std::size_t i) : owner_(owner), i_(i) {}
    Value operator*() const;
    iterator& operator++() {
      ++i_;
      return *this;
    }
    bool operator!=(const iterator& other) const { return i_ != other.i_; }

   private:
    const TreeNode* owner_;
    std::size_t i_;
  };
  explicit TreeRange(TreeNode owner) : owner_(owner) {}
  iterator begin() const { return {&owner_, 0}; }
  iterator end() const { return {&owner_, owner_.size()}; }

 private:
  TreeNode owner_;
};

template <>
inline TreeNode TreeRange<TreeNode>::iterator::operator*() const {
  return (*owner_)[i_];
}
template <>
inline TreeEntry TreeRange<TreeEntry>::iterator::operator*() const {
  return {owner_->key(i_), owner_->value(i_)};
}
inline TreeRange<TreeNode> TreeNode::items() const { return TreeRange<TreeNode>(is_sequence() ? *this : TreeNode()); }
inline TreeRange<TreeEntry> TreeNode::entries() const { return TreeRange<TreeEntry>(is_map() ? *this : TreeNode()); }

/// The storage behind TreeNode handles. Filled by the reader in yaml_support.cpp.
class ModelTree {
 public:
  /// One node: where it starts and what it holds. For a scalar, [begin, begin + count) is its
  /// text in the pool; for a sequence (map), its items (key, value pairs) are
  /// children_[begin, begin + count) (twice `count` entries for a map).
  struct Record {
    std::uint32_t line = 0, column = 0;
    std::uint32_t begin = 0, count = 0;
    TreeNode::Kind kind = TreeNode::Kind::undefined;
  };

  TreeNode root() const { return records_.empty() ? TreeNode() : TreeNode(this, root_); }
  /// Node `index` (in the order added), e.g. a container still being built.
  TreeNode node(std::uint32_t index) const { return index < records_.size() ? TreeNode(this, index) : TreeNode(); }
  std::size_t node_count() const { return records_.size(); }

  /// Appends a node and returns its index (used while building).
  std::uint32_t add(const Record& record) {
    records_.push_back(record);
    return static_cast<std::uint32_t>(records_.size() - 1);
  }
  /// Appends scalar text to the pool; returns its offset.
  std::uint32_t add_text(std::string_view text) {
    const auto offset = static_cast<std::uint32_t>(text_.size());
    text_.append(text);
    return offset;
  }
  /// Stores the children of container `index` (kept contiguous) and closes it.
  void set_children(std::uint32_t index, const std::vector<std::uint32_t>& children, bool map) {
    Record& record = records_[index];
    record.begin = static_cast<std::uint32_t>(children_.size());
    record.count = static_cast<std::uint32_t>(map ? children.size() / 2 : children.size());
    children_.insert(children_.end(), children.begin(), children.end());
  }
  void set_root(std::uint32_t index) { root_ = index; }
  /// Room for `nodes` nodes and `text` bytes of scalar text before the tree is built, so that
  /// it is not copied while it grows (nor once more to give back the slack). Room that is never
  /// written is address space only: the pages are not touched.
  void reserve(std::size_t nodes, std::size_t text) {
    records_.reserve(nodes);
    children_.reserve(nodes);
    text_.reserve(text);
  }

 private:
  friend class TreeNode;
  std::vector<Record> records_;
  std::vector<std::uint32_t> children_;
  std::string text_;
  std::uint32_t root_ = 0;
};

// The accessors every reader calls per node, inline.
inline TreeNode::Kind TreeNode::kind() const { return tree_ ? tree_->records_[index_].kind : Kind::undefined; }

inline std::string_view TreeNode::scalar() const {
  if (kind() != Kind::scalar) return {};
  const ModelTree::Record& record = tree_->records_[index_];
  return std::string_view(tree_->text_).substr(record.begin, record.count);
}

inline std::size_t TreeNode::size() const {
  const Kind k = kind();
  return k == Kind::sequence || k == Kind::map ? tree_->records_[index_].count : 0;
}

inline TreeNode TreeNode::operator[](std::size_t i) const {
  if (kind() != Kind::sequence || i >= size()) return {};
  return {tree_, tree_->children_[tree_->records_[index_].begin + i]};
}

inline TreeNode TreeNode::key(std::size_t i) const {
  if (kind() != Kind::map || i >= size()) return {};
  return {tree_, tree_->children_[tree_->records_[index_].begin + 2 * i]};
}

inline TreeNode TreeNode::value(std::size_t i) const {
  if (kind() != Kind::map || i >= size()) return {};
  return {tree_, tree_->children_[tree_->records_[index_].begin + 2 * i + 1]};
}

inline int TreeNode::line() const { return tree_ ? static_cast<int>(tree_->records_[index_].line) : 0; }
inline int TreeNode::column() const { return tree_ ? static_cast<int>(tree_->records_[index_].column) : 0; }

}  // namespace kinestat::io
