// SPDX-License-Identifier: BSD-3-Clause
// kinestat: how free and how constrained is a mechanism, a compliant mechanism or a structure?
#include "cli/commands.hpp"
#include "cli/process/process_setup.hpp"

int main(int argc, char** argv) {
  kinestat::cli::process::set_up_process(argc, argv);
  return kinestat::cli::run(argc, argv);
}
