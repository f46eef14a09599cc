// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reads the kinematic part of a SPACAR input file (.dat, as written by hand or by SPACAR
// Light) into a FrameworkModel: X, BEAM, BEAMW, TRUSS, HINGE, PINBODY, PLBEAM, PLTRUSS,
// PLHINGE, DYNE, RLSE, INPUTE, FIX, INPUTX and DYNX (noted: it fixes nothing) up to the first
// END or HALT; '#' and '%' start comments. How each keyword maps is in docs/formats.md.
// Every problem is an InputError at file:line:column.

#include <string>
#include <vector>

#include "kinestat/framework/framework_model.hpp"
#include "kinestat/io/network_import.hpp"

namespace kinestat::io {

/// A SPACAR file read into kinestat's framework model, with one line per thing that was
/// read but has no kinematic meaning (warping, stiffness, loads, visualisation, ...).
struct SpacarImport {
  framework::FrameworkModel model;
  std::vector<std::string> notices;
};

/// Reads SPACAR input `text` that came from `path` (used in messages only). Text longer than
/// `options.max_input_bytes` (the command's --max-input-size) is refused with an InputError
/// naming the file and the limit; the other options do not apply to SPACAR files.
SpacarImport parse_spacar(const std::string& path, const std::string& text, const ImportOptions& options = {});

/// Reads the SPACAR input file at `path`, at most `options.max_input_bytes` of it. Throws
/// InputError if it cannot be read or is larger.
SpacarImport read_spacar(const std::string& path, const ImportOptions& options = {});

/// Name of the kinestat node for SPACAR position node `position` ("3"), and of the extra
/// node that carries orientation node `orientation` at a position whose first orientation
/// node is another one ("3r8": a joint, see docs/formats.md).
std::string spacar_node_name(long position);
std::string spacar_joint_node_name(long position, long orientation);

}  // namespace kinestat::io
