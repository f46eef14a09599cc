// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The `kinestat` command's rand() and srand(): one state per thread (thread_local_rand.cpp).

namespace kinestat::cli {

/// Tells the library (linalg::set_thread_local_rand) that this process's rand() keeps one state
/// per thread, once the dynamic linker is seen to use the command's own definition (so that
/// METIS, in a shared library, draws from it): large networks then factor K and Kᵀ side by side.
void declare_thread_local_rand();

}  // namespace kinestat::cli
