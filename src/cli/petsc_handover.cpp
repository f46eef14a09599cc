// SPDX-License-Identifier: BSD-3-Clause
// `kinestat analyze --backend petsc`: handed over to `kinestat-mpi`, the same command line
// interface built with the distributed backend (distributed/petsc_backend.cpp), found beside
// this executable. Linking the backend (then PETSc, SLEPc and MPI) into `kinestat` itself made
// every command load about 120 shared libraries at startup (0.1-0.2 s of CPU before the first
// line of work); now only `--backend petsc` loads MPI. The handover replaces this process (execv) before MPI
// is initialised, so under mpirun each rank simply becomes a `kinestat-mpi` process.

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include "cli/commands.hpp"

namespace kinestat::cli {

#if KINESTAT_PETSC_HANDOVER

namespace {

// This process's arguments as the kernel keeps them (NUL-separated), so that kinestat-mpi parses
// exactly what this process parsed.
std::vector<std::string> own_arguments() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  const std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::string> arguments;
  for (std::size_t start = 0; start < all.size();) {
    const std::size_t end = std::min(all.find('\0', start), all.size());
    arguments.push_back(all.substr(start, end - start));
    start = end + 1;
  }
  return arguments;
}

}  // namespace

int run_petsc_analysis(const CommonOptions&) {
  std::error_code ignored;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ignored);
  const std::filesystem::path backend = self.parent_path() / "kinestat-mpi";
  std::vector<std::string> arguments = own_arguments();
  if (arguments.empty()) throw Error("--backend petsc: this process's arguments cannot be read from /proc/self/cmdline");
  std::vector<char*> argv;
  for (std::string& argument : arguments) argv.push_back(argument.data());
  argv.push_back(nullptr);
  std::cout.flush();
  std::cerr.flush();
  ::execv(backend.c_str(), argv.data());
  // Only reached when the exec failed.
  throw Error(fmt::format("--backend petsc runs {}, the distributed backend installed beside kinestat, and it cannot be "
                          "started ({}); reinstall kinestat, or run kinestat-mpi directly",
                          backend.string(), std::strerror(errno)));
}

#else

int run_petsc_analysis(const CommonOptions&) {
  throw Error("--backend petsc needs the distributed backend, and this kinestat was built without it "
              "(install libopenmpi-dev openmpi-bin and configure with -DKINESTAT_PETSC=ON)");
}

#endif

}  // namespace kinestat::cli
