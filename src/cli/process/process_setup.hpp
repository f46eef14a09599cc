// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The `kinestat` command's process: everything it sets for the whole process, in one place, before
// any work. The library never sets process-wide state, reads the environment or starts threads.

namespace kinestat::cli::process {

/// Sets up the command's process, first thing in main(): a restart on transparent huge pages for
/// an input file of 1 MiB or more (huge_pages.cpp), OpenBLAS on KINESTAT_BLAS_THREADS threads
/// (default 1, its idle workers ended) and glibc's heap keeping freed memory for reuse in one
/// arena. May not return (the restart replaces the process).
void set_up_process(int argc, char** argv);

/// OpenBLAS's thread count, once per process: KINESTAT_BLAS_THREADS when a positive number, else
/// 1 (machines are often shared, and a fixed count keeps results independent of the machine).
/// With one thread its worker threads, started when it was loaded, are ended. For set_up_process
/// and the benchmarks.
void pin_blas_threads();

}  // namespace kinestat::cli::process
