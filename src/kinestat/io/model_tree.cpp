#include "kinestat/io/model_tree.hpp"

namespace kinestat::io {

TreeNode::Kind TreeNode::kind() const { return tree_ ? tree_->records_[index_].kind : Kind::undefined; }

std::string_view TreeNode::scalar() const {
  if (kind() != Kind::scalar) return {};
  const ModelTree::Record& record = tree_->records_[index_];
  return std::string_view(tree_->text_).substr(record.begin, record.count);
}

std::size_t TreeNode::size() const {
  const Kind k = kind();
  return k == Kind::sequence || k == Kind::map ? tree_->records_[index_].count : 0;
}

TreeNode TreeNode::operator[](std::size_t i) const {
  if (kind() != Kind::sequence || i >= size()) return {};
  return {tree_, tree_->children_[tree_->records_[index_].begin + i]};
}

TreeNode TreeNode::key(std::size_t i) const {
  if (kind() != Kind::map || i >= size()) return {};
  return {tree_, tree_->children_[tree_->records_[index_].begin + 2 * i]};
}

TreeNode TreeNode::value(std::size_t i) const {
  if (kind() != Kind::map || i >= size()) return {};
  return {tree_, tree_->children_[tree_->records_[index_].begin + 2 * i + 1]};
}

TreeNode TreeNode::operator[](std::string_view name) const {
  for (std::size_t i = 0; i < size() && is_map(); ++i) {
    const TreeNode k = key(i);
    if (k.is_scalar() && k.scalar() == name) return value(i);
  }
  return {};
}

int TreeNode::line() const { return tree_ ? static_cast<int>(tree_->records_[index_].line) : 0; }
int TreeNode::column() const { return tree_ ? static_cast<int>(tree_->records_[index_].column) : 0; }

}  // namespace kinestat::io
