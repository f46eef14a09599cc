#pragma once
// The SPACAR keywords kinestat reads and writes (docs/formats.md), shared by the SPACAR
// reader and writer so that both agree on what each element keyword means.

#include <optional>
#include <string_view>

namespace kinestat::io::spacar {

/// What an element keyword is: a beam (with orientation nodes) or a truss, planar or spatial.
struct ElementKeyword {
  bool beam = false;
  bool planar = false;
};

/// The element keywords kinestat reads: BEAM, BEAMW, TRUSS, PLBEAM, PLTRUSS (upper case).
inline std::optional<ElementKeyword> element_keyword(std::string_view keyword) {
  if (keyword == "BEAM" || keyword == "BEAMW") return ElementKeyword{true, false};
  if (keyword == "TRUSS") return ElementKeyword{false, false};
  if (keyword == "PLBEAM") return ElementKeyword{true, true};
  if (keyword == "PLTRUSS") return ElementKeyword{false, true};
  return std::nullopt;
}

/// Keywords that give deformations (DYNE, RLSE, INPUTE) or coordinates (FIX, INPUTX) a role.
inline bool is_role_keyword(std::string_view keyword) {
  return keyword == "DYNE" || keyword == "RLSE" || keyword == "INPUTE" || keyword == "FIX" || keyword == "INPUTX";
}

/// Keywords allowed in the kinematic part that only control SPACAR's own output.
inline bool is_output_keyword(std::string_view keyword) { return keyword == "OUTLEVEL"; }

inline constexpr std::string_view kSupportedKeywords =
    "X, BEAM, BEAMW, TRUSS, PLBEAM, PLTRUSS, DYNE, RLSE, INPUTE, FIX and INPUTX";

}  // namespace kinestat::io::spacar
