// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// kinestat's dense kernels (LAPACK's SVD, SuiteSparse's frontal matrices) run on Debian's
// OpenBLAS. Its thread count is pinned rather than left to the machine.

namespace kinestat::linalg {

/// Pins the number of OpenBLAS threads once per process: KINESTAT_BLAS_THREADS when set to a
/// positive number, else 1 — machines are often shared, and a fixed count keeps floating-point
/// results independent of the machine. With one thread, OpenBLAS's worker threads (started
/// when it is loaded, and spinning for a while when idle) are ended. Called by every routine
/// that uses BLAS, and first thing by the command line tool.
void pin_blas_threads();

}  // namespace kinestat::linalg
