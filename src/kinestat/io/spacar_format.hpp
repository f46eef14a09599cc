// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The SPACAR keywords kinestat reads and writes (docs/formats.md), shared by the SPACAR
// reader and writer so that both agree on what each element keyword means.

#include <optional>
#include <string_view>

namespace kinestat::io::spacar {

/// What an element keyword describes: a truss (two position nodes), a beam (position and
/// orientation node at each end), a hinge (two orientation nodes) or a pin body (a position and
/// orientation node of a body and a position node it carries) or a rigid beam (RBEAM: a position
/// and orientation node at p and a position node q without an orientation); planar or spatial.
enum class ElementKind { truss, beam, hinge, pin_body, rigid_beam };

struct ElementKeyword {
  ElementKind kind = ElementKind::truss;
  bool planar = false;
};

/// The element keywords kinestat reads: BEAM, BEAMW, TRUSS, HINGE, PINBODY, PLBEAM, PLTRUSS,
/// PLHINGE, RBEAM (upper case).
inline std::optional<ElementKeyword> element_keyword(std::string_view keyword) {
  if (keyword == "BEAM" || keyword == "BEAMW") return ElementKeyword{ElementKind::beam, false};
  if (keyword == "TRUSS") return ElementKeyword{ElementKind::truss, false};
  if (keyword == "HINGE") return ElementKeyword{ElementKind::hinge, false};
  if (keyword == "PINBODY") return ElementKeyword{ElementKind::pin_body, false};
  if (keyword == "RBEAM") return ElementKeyword{ElementKind::rigid_beam, false};
  if (keyword == "PLBEAM") return ElementKeyword{ElementKind::beam, true};
  if (keyword == "PLTRUSS") return ElementKeyword{ElementKind::truss, true};
  if (keyword == "PLHINGE") return ElementKeyword{ElementKind::hinge, true};
  return std::nullopt;
}

/// Keywords that give deformations (DYNE, RLSE, INPUTE) or coordinates (FIX, INPUTX) a role.
inline bool is_role_keyword(std::string_view keyword) {
  return keyword == "DYNE" || keyword == "RLSE" || keyword == "INPUTE" || keyword == "FIX" || keyword == "INPUTX";
}

/// Keywords of SPACAR's dynamic analysis allowed in the kinematic part: DYNX (the nodal
/// coordinates that are dynamic degrees of freedom). Read and checked; they fix nothing.
inline bool is_dynamic_keyword(std::string_view keyword) { return keyword == "DYNX"; }

/// Keywords allowed in the kinematic part that only control SPACAR's own output.
inline bool is_output_keyword(std::string_view keyword) { return keyword == "OUTLEVEL"; }

inline constexpr std::string_view kSupportedKeywords =
    "X, BEAM, BEAMW, RBEAM, TRUSS, HINGE, PINBODY, PLBEAM, PLTRUSS, PLHINGE, DYNE, RLSE, INPUTE, FIX, INPUTX and DYNX";

}  // namespace kinestat::io::spacar
