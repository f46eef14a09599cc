// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/linalg/concurrent_orderings.hpp"

#include <atomic>

namespace kinestat::linalg {

namespace {
std::atomic<bool> thread_local_rand{false};
}  // namespace

void set_thread_local_rand(bool per_thread) { thread_local_rand.store(per_thread); }

bool concurrent_orderings_allowed() { return thread_local_rand.load(); }

}  // namespace kinestat::linalg
