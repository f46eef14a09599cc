// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The command restarted on transparent huge pages for large inputs (huge_pages.cpp).

namespace kinestat::cli::process {

/// When an argument names a regular file of 1 MiB or more and GLIBC_TUNABLES does not name
/// glibc.malloc.hugetlb, starts this program again (execv of /proc/self/exe, the same
/// arguments) with glibc.malloc.hugetlb=1 and OpenBLAS's thread count in the environment.
/// Returns when no restart is needed or possible.
void restart_on_huge_pages_for_large_input(int argc, char** argv);

}  // namespace kinestat::cli::process
