// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/model_kind.hpp"

namespace kinestat::io {

std::optional<ModelKind> kind_named(std::string_view name) {
  for (const ModelKind kind : {ModelKind::network, ModelKind::framework, ModelKind::structure})
    if (kind_name(kind) == name) return kind;
  return std::nullopt;
}

}  // namespace kinestat::io
