// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/model_tree.hpp"

namespace kinestat::io {

TreeNode TreeNode::operator[](std::string_view name) const {
  for (std::size_t i = 0; i < size() && is_map(); ++i) {
    const TreeNode k = key(i);
    if (k.is_scalar() && k.scalar() == name) return value(i);
  }
  return {};
}

}  // namespace kinestat::io
