// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/network/network_result.hpp"

namespace kinestat::network {

NetworkClass classify(int FN, int CN) {
  return FN == 0 ? (CN == 0 ? NetworkClass::simply_stiff : NetworkClass::overconstrained_structure)
                 : (CN == 0 ? NetworkClass::kinematic_chain : NetworkClass::overconstrained_chain);
}

std::string class_id(NetworkClass c) {
  switch (c) {
    case NetworkClass::simply_stiff: return "simply_stiff_structure";
    case NetworkClass::overconstrained_structure: return "overconstrained_structure";
    case NetworkClass::kinematic_chain: return "kinematically_designed_chain";
    case NetworkClass::overconstrained_chain: return "overconstrained_chain";
  }
  return "unknown";
}

std::string class_description(NetworkClass c) {
  switch (c) {
    case NetworkClass::simply_stiff: return "simply stiff / statically determinate structure (FN = 0, CN = 0)";
    case NetworkClass::overconstrained_structure:
      return "redundant / statically indeterminate / overconstrained structure (FN = 0, CN > 0)";
    case NetworkClass::kinematic_chain: return "kinematically designed (exactly constrained) kinematic chain (FN > 0, CN = 0)";
    case NetworkClass::overconstrained_chain:
      return "overconstrained kinematic chain; a mechanism once ports are selected (FN > 0, CN > 0)";
  }
  return "unknown";
}

}  // namespace kinestat::network
