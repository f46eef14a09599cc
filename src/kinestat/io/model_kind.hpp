// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The three kinds of model kinestat analyses, as one enum for every layer: files spell the kind
// as a word (`kind: network`), programs compare the enum.

#include <optional>
#include <string_view>

namespace kinestat::io {

/// The `kind:` of a model file.
enum class ModelKind { network, framework, structure };

/// The spelling of `kind` in model files and reports: "network", "framework" or "structure".
std::string_view kind_name(ModelKind kind);

/// The kind spelled `name` ("network", "framework" or "structure"); none for any other word.
std::optional<ModelKind> kind_named(std::string_view name);

}  // namespace kinestat::io
