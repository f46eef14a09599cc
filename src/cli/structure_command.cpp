// Placeholder until the structural-group analysis lands; replaced by its real implementation.
#include "cli/commands.hpp"

namespace kinestat::cli {
void register_structure(CLI::App&, Action&) {}
}  // namespace kinestat::cli
