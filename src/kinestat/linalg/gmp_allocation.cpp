// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/linalg/gmp_allocation.hpp"

#include <gmp.h>

#include <cstdlib>
#include <mutex>
#include <new>

namespace kinestat::linalg {

namespace {

void* allocate(std::size_t size) {
  void* block = std::malloc(size);
  if (block == nullptr && size > 0) throw std::bad_alloc();
  return block;
}

void* reallocate(void* block, std::size_t /*old_size*/, std::size_t new_size) {
  void* moved = std::realloc(block, new_size);
  if (moved == nullptr && new_size > 0) throw std::bad_alloc();
  return moved;
}

void release(void* block, std::size_t /*size*/) { std::free(block); }

}  // namespace

void install_throwing_gmp_allocation() {
  static std::once_flag once;
  std::call_once(once, [] { mp_set_memory_functions(allocate, reallocate, release); });
}

}  // namespace kinestat::linalg
