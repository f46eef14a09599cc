// SPDX-License-Identifier: BSD-3-Clause
// rand() and srand() with one state per thread, for METIS. METIS (through SuiteSparse's
// orderings) seeds with srand() at the start of each ordering and then draws with rand(); glibc
// keeps one state for the whole process, so two orderings on two threads would interleave their
// draws and the fill orders would depend on timing. These definitions in the executable come
// before the C library's in the dynamic linker's search (the link exports them), and each thread
// keeps glibc's own generator (random_r on a 128-byte TYPE_3 state, what rand() uses), so each
// ordering draws exactly the sequence it draws alone.

#include "cli/process/thread_local_rand.hpp"

#include <dlfcn.h>

#include <cstdint>
#include <cstdlib>

namespace {

struct RandState {
  random_data data{};  // zeroed: initstate_r requires it
  char state[128]{};   // 128 bytes select TYPE_3, rand()'s own generator
  bool started = false;
};

thread_local RandState rand_state;

void seed_rand(unsigned int seed) {
  if (!rand_state.started) {
    initstate_r(seed, rand_state.state, sizeof rand_state.state, &rand_state.data);
    rand_state.started = true;
  } else {
    srandom_r(seed, &rand_state.data);
  }
}

}  // namespace

extern "C" void srand(unsigned int seed) noexcept { seed_rand(seed); }

extern "C" int rand() noexcept {
  if (!rand_state.started) seed_rand(1);  // glibc's rand() before any srand(): seed 1
  std::int32_t value = 0;
  random_r(&rand_state.data, &value);
  return value;
}

namespace kinestat::cli::process {

bool thread_local_rand_bound() {
  // Only when a shared library would bind to these definitions (the executable exports them).
  return ::dlsym(RTLD_DEFAULT, "rand") == reinterpret_cast<void*>(&rand) &&
         ::dlsym(RTLD_DEFAULT, "srand") == reinterpret_cast<void*>(&srand);
}

}  // namespace kinestat::cli::process
