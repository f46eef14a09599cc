// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Writes a framework model as the kinematic part of a SPACAR input file (docs/formats.md):
// X, BEAM / PLBEAM, TRUSS / PLTRUSS, RLSE, INPUTE, FIX and INPUTX, numbered as SPACAR Light
// numbers its nodes (position node 2i−1, orientation node 2i for the i-th node).

#include <string>

#include "kinestat/framework/framework_model.hpp"

namespace kinestat::io {

/// What to write besides the model itself.
struct SpacarWriteOptions {
  std::string source;  ///< named in the header comment
  /// The model with kinestat's proposal applied (framework::apply_proposal); its extra
  /// releases and inputs are written as RLSE / INPUTX lines, commented out for pasting
  /// unless `apply_proposal` is set.
  const framework::FrameworkModel* proposed = nullptr;
  bool apply_proposal = false;
};

/// The SPACAR text of `model`. Throws InputError (naming `options.source`) for what SPACAR
/// cannot express: a rigid body with released deformations other than a joint, or a rigid
/// body whose nodes coincide.
std::string spacar_text(const framework::FrameworkModel& model, const SpacarWriteOptions& options = {});

}  // namespace kinestat::io
