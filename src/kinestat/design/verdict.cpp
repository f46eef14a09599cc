#include "kinestat/design/verdict.hpp"

#include <fmt/format.h>

namespace kinestat::design {

namespace {
std::string counted(int n, const char* one, const char* many) { return fmt::format("{} {}", n, n == 1 ? one : many); }
}  // namespace

std::string constraint_words(int extra_motions, int redundant_constraints) {
  if (extra_motions == 0 && redundant_constraints == 0) return "exactly constrained";
  std::string words;
  if (extra_motions > 0) words = counted(extra_motions, "extra motion", "extra motions");
  if (redundant_constraints > 0) {
    if (!words.empty()) words += ", ";
    words += counted(redundant_constraints, "redundant constraint", "redundant constraints");
  }
  return words;
}

std::string summary_sentence(int extra_motions, int redundant_constraints, int intended_motions) {
  const std::string motions = intended_motions == 0 ? "a structure (no intended motion)"
                                                    : counted(intended_motions, "intended motion", "intended motions");
  if (extra_motions == 0 && redundant_constraints == 0) return fmt::format("Exactly constrained: {}.", motions);
  return fmt::format("Not exactly constrained: {} ({}).", constraint_words(extra_motions, redundant_constraints), motions);
}

}  // namespace kinestat::design
