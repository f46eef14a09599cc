// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The model of a parameter sweep as text with a hole for each parameter: every variant is the
// model file with the parameters' literals written in place of the numbers they address, read
// and analysed exactly as `kinestat analyze` would read and analyse that file (docs/sweep.md).

#include <cstddef>
#include <string>
#include <vector>

#include "kinestat/io/sweep_spec.hpp"

namespace kinestat::io {

/// Where a number literal stands in a model file's text (bytes).
struct NumberSlot {
  std::size_t offset = 0;
  std::size_t length = 0;
};

/// The model of a sweep, ready to make variants.
struct SweepModel {
  std::string path;                ///< names the model (and every variant) in messages
  std::string text;                ///< the model file as read
  std::string kind;                ///< "framework" or "network"
  std::vector<NumberSlot> slots;   ///< one per parameter of the spec, in the spec's order
};

/// Parses `text` (the model file named by `path` in messages), checks that it is a valid framework
/// or network model, and finds the number each parameter of `spec` addresses. Throws InputError:
/// at the model for a bad model, at the parameter in the spec for an address that names nothing,
/// or names something other than a plain number literal.
SweepModel prepare_sweep_model(const SweepSpec& spec, const std::string& path, const std::string& text);

/// The text of the variant whose parameters take `literals` (one per slot, e.g. from
/// design::number_literal).
std::string variant_text(const SweepModel& model, const std::vector<std::string>& literals);

}  // namespace kinestat::io
