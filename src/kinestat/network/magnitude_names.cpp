// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/network/magnitude_names.hpp"

#include <cctype>
#include <set>

namespace kinestat::network {

namespace {
std::string kind_word(screw::UnitScrewKind kind) {
  switch (kind) {
    case screw::UnitScrewKind::rotation: return "rot";
    case screw::UnitScrewKind::translation: return "tra";
    case screw::UnitScrewKind::twist: return "twist";
    case screw::UnitScrewKind::torque: return "torque";
    case screw::UnitScrewKind::force: return "force";
    case screw::UnitScrewKind::wrench: return "wrench";
    case screw::UnitScrewKind::general: break;
  }
  return "screw";
}
}  // namespace

std::string magnitude_name(const std::string& coupling_name, const screw::UnitScrew& screw, int index) {
  const bool single_letter = coupling_name.size() == 1 && std::isalpha(static_cast<unsigned char>(coupling_name[0]));
  if (screw.letter != 0 && single_letter)
    return std::string(1, screw.letter) + static_cast<char>(std::tolower(static_cast<unsigned char>(coupling_name[0])));
  const std::string stem = screw.letter != 0 ? std::string(1, screw.letter) : kind_word(screw.kind) + std::to_string(index + 1);
  return stem + "_" + coupling_name;
}

void make_unique(std::vector<std::string>& names) {
  std::set<std::string> seen;
  for (std::string& name : names) {
    while (!seen.insert(name).second) name += "'";
  }
}

}  // namespace kinestat::network
