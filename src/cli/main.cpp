// SPDX-License-Identifier: BSD-3-Clause
// kinestat: how free and how constrained is a mechanism, a compliant mechanism or a structure?
#include "cli/commands.hpp"
#include "cli/thread_local_rand.hpp"

int main(int argc, char** argv) {
  kinestat::cli::restart_on_huge_pages_for_large_input(argc, argv);
  kinestat::cli::declare_thread_local_rand();
  return kinestat::cli::run(argc, argv);
}
