#pragma once
// Reads a `kind: framework` model file (docs/framework.md) into a FrameworkModel. Every
// problem is an InputError at the offending node: file:line:column: error: what.

#include "kinestat/framework/framework_model.hpp"
#include "kinestat/io/yaml_support.hpp"

namespace kinestat::io {

/// Relative tolerance for triads: |R Rᵀ − I| (largest entry) and the alignment of axes with
/// elements must be within this, so that 7-digit decimals such as 0.7071068 are accepted.
inline constexpr double kOrientationTolerance = 1e-6;
/// An element shorter than this fraction of the model's characteristic length has zero length.
inline constexpr double kZeroLength = 1e-12;

/// Builds the model from `file` (already checked for `kinestat: 1` and `kind: framework`).
framework::FrameworkModel read_framework(const YamlFile& file);

}  // namespace kinestat::io
