// Placeholder until the network analysis lands; replaced by its real implementation.
#include <iostream>

#include "cli/commands.hpp"

namespace kinestat::cli {
void register_network_options(CLI::App&) {}
int run_network_analysis(const CommonOptions&, const io::YamlFile& model) {
  throw io::InputError({model.path(), 1, 1}, "network analysis is not available in this build");
}
}  // namespace kinestat::cli
