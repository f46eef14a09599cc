// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// SuiteSparse's METIS orderings draw from the C library's rand(), whose state glibc keeps once
// per process: two orderings on two threads would interleave their draws, so each fill order
// (and with it a factor's close rank decisions and supports) would depend on timing. The
// library runs factorisations side by side only where the process has declared that every
// thread has its own rand() state; otherwise one after the other, which is the same answer.

namespace kinestat::linalg {

/// Declares whether rand() and srand() keep one state per thread in this process, each drawing
/// the sequence glibc's rand() draws for the same seed (the `kinestat` command defines them so).
/// Default false. Thread-safe.
void set_thread_local_rand(bool per_thread);

/// Whether two sparse factorisations with METIS orderings may run at the same time and still give
/// exactly what they give one after the other (set_thread_local_rand(true) was declared).
bool concurrent_orderings_allowed();

}  // namespace kinestat::linalg
