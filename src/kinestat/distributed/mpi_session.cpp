// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/distributed/mpi_session.hpp"

#include <mpi.h>

#include <cstdlib>
#include <stdexcept>
#include <string_view>

namespace kinestat::distributed {

namespace {

bool mpi_running() {
  int initialised = 0, finalised = 0;
  MPI_Initialized(&initialised);  // both may be called before MPI_Init
  MPI_Finalized(&finalised);
  return initialised != 0 && finalised == 0;
}

}  // namespace

bool started_alone(const char* const* environment) {
  bool launcher = false, sized = false, sized_one = true;
  for (const char* const* entry = environment; entry != nullptr && *entry != nullptr; ++entry) {
    const std::string_view variable(*entry);
    const std::size_t equals = variable.find('=');
    if (equals == std::string_view::npos) continue;
    const std::string_view name = variable.substr(0, equals), value = variable.substr(equals + 1);
    if (name == "OMPI_COMM_WORLD_SIZE" || name == "PMI_SIZE") {
      sized = true;
      sized_one = sized_one && value == "1";
    }
    if (name.starts_with("OMPI_COMM_WORLD_") || name.starts_with("PMI_") || name.starts_with("PMIX_")) launcher = true;
  }
  return sized ? sized_one : !launcher;
}

MpiSession::MpiSession(bool initialise) {
  if (!initialise) return;
  if (MPI_Init(nullptr, nullptr) != MPI_SUCCESS) throw std::runtime_error("MPI could not be initialised");
  initialised_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() {
  if (initialised_) MPI_Finalize();
}

void MpiSession::abort(int exit_code) {
  if (mpi_running()) MPI_Abort(MPI_COMM_WORLD, exit_code);
  std::exit(exit_code);
}

int world_rank() {
  int rank = 0;
  if (mpi_running()) MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

int world_size() {
  int size = 1;
  if (mpi_running()) MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

}  // namespace kinestat::distributed
