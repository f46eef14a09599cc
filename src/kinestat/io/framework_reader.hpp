// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reads a `kind: framework` model file (docs/framework.md) into a FrameworkModel. Every
// problem is an InputError at the offending node: file:line:column: error: what.

#include "kinestat/framework/framework_model.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::io {


/// Builds the model from `file` (already checked for `kinestat: 1` and `kind: framework`).
framework::FrameworkModel read_framework_model(const YamlFile& file);

}  // namespace kinestat::io
