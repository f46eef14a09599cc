// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The `kinestat` command's rand() and srand(): one state per thread (thread_local_rand.cpp).

namespace kinestat::cli::process {

/// Whether the dynamic linker binds rand() and srand() to the command's own definitions (one
/// state per thread, exported by the executable), so that METIS, in a shared library, draws
/// from them: then two METIS orderings may run at once with the answer of one after the other.
bool thread_local_rand_bound();

}  // namespace kinestat::cli::process
