// Placeholder until the framework analysis lands; replaced by its real implementation.
#include <iostream>

#include "cli/commands.hpp"

namespace kinestat::cli {
void register_framework_options(CLI::App&) {}
int run_framework_analysis(const CommonOptions&, const io::YamlFile& model) {
  throw io::InputError({model.path(), 1, 1}, "framework analysis is not available in this build");
}
}  // namespace kinestat::cli
