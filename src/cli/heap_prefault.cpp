// SPDX-License-Identifier: BSD-3-Clause
// The heap's pages faulted in on the idle core. On virtual machines the first write to a fresh
// page costs 0.3-1.5 GB/s (the kernel clears it; bench/README.md), and a large analysis touches
// most of its memory once: a fifth of a 10^6-bar lattice's command was the kernel clearing pages
// on the one thread that works, while the other core was idle. So a command given a large input
// file extends the heap at once by an estimate of what the next stage will use and frees it again
// (the trim threshold keeps it mapped; no separate mappings, run.cpp), and a background thread
// faults those pages in with madvise(MADV_POPULATE_WRITE), which fills the page tables without
// writing to the memory: safe while the main thread already allocates and writes in the same
// pages. The caller's estimates stay below what was measured, so that no page is faulted in that
// the analysis would not have touched.

#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <system_error>
#include <thread>

#include "cli/commands.hpp"
#include "kinestat/address_sanitizer.hpp"

namespace kinestat::cli {

namespace {

#ifndef MADV_POPULATE_WRITE
constexpr int MADV_POPULATE_WRITE = 23;  // Linux 5.14; older kernels refuse it (EINVAL) and nothing happens
#endif

// At most this share of the memory still available, so a prefault never presses on a busy machine.
constexpr std::uintmax_t kMaxShareOfAvailable = 4;  // one quarter
// Below run.cpp's trim threshold (1 GiB), so that the free leaves the pages in the heap.
constexpr std::uintmax_t kMaxHeapPrefaultBytes = (std::uintmax_t{1} << 30) - (std::uintmax_t{64} << 20);
constexpr std::size_t kPopulateStep = std::size_t{2} << 20;

std::uintmax_t available_memory_bytes() {
  const long pages = ::sysconf(_SC_AVPHYS_PAGES);
  const long page_size = ::sysconf(_SC_PAGESIZE);
  return pages > 0 && page_size > 0 ? static_cast<std::uintmax_t>(pages) * static_cast<std::uintmax_t>(page_size) : 0;
}

// Extends the heap by `bytes` (capped), frees them again and faults their pages in on a
// background thread.
void prefault_heap(std::uintmax_t bytes) {
  if (kBuiltWithAddressSanitizer) return;  // its allocator keeps freed blocks in quarantine, not in the heap
  const char* disabled = std::getenv("KINESTAT_PREFAULT");
  if (disabled != nullptr && disabled[0] == '0') return;
  const auto length = static_cast<std::size_t>(
      std::min({bytes, available_memory_bytes() / kMaxShareOfAvailable, kMaxHeapPrefaultBytes}));
  if (length < 2 * kPopulateStep) return;
  // With no separate mappings the block is the heap's top, extended as far as needed; freed, it
  // stays mapped as the top chunk, from whose start the next allocations are carved.
  void* block = std::malloc(length);
  if (block == nullptr) return;
  // madvise wants whole pages: the block's page-aligned inside.
  const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
  const std::uintptr_t first = (reinterpret_cast<std::uintptr_t>(block) + page - 1) / page * page;
  const std::uintptr_t last = (reinterpret_cast<std::uintptr_t>(block) + length) / page * page;
  std::free(block);
  try {
    std::thread([start = reinterpret_cast<char*>(first), pages_length = static_cast<std::size_t>(last - first)] {
      for (std::size_t offset = 0; offset < pages_length; offset += kPopulateStep)
        if (::madvise(start + offset, std::min(kPopulateStep, pages_length - offset), MADV_POPULATE_WRITE) != 0) return;
    }).detach();
  } catch (const std::system_error&) {
    // no thread to be had (a process limit): the analysis faults its pages in itself, as before
  }
}

// Below this the heap a command uses is small enough that clearing its pages does not matter.
constexpr std::uintmax_t kPrefaultInputBytes = std::uintmax_t{1} << 20;

// Heap per byte of input, the two stages together below the peak RSS over the input's size
// measured (bench/README.md, session 18): 21 for a 10^5-bar cubic lattice (104 MB of 5.0 MB),
// 24 for a 10^6-bar triangular one (1,357 MB of 56 MB), 68-100 for networks of 10^5 couplings.
// The parsed tree alone: 5.5 (the triangular lattice) to 22 (the networks). Networks get the
// tree's share only: their factorisations keep both cores busy, and more (40 or 70 per byte)
// changed a ladder of 10^5 couplings' time by 1-2 %, within the noise.
constexpr std::uintmax_t kTreeBytesPerInputByte = 5;
constexpr std::uintmax_t kFrameworkBytesPerInputByte = 10;

}  // namespace

void prefault_heap_for_reading(const std::string& model_path) {
  const std::uintmax_t input_bytes = regular_file_bytes(model_path);
  if (input_bytes >= kPrefaultInputBytes) prefault_heap(kTreeBytesPerInputByte * input_bytes);
}

void prefault_heap_for_analysis(const std::string& model_path, std::string_view kind) {
  const std::uintmax_t input_bytes = regular_file_bytes(model_path);
  if (input_bytes < kPrefaultInputBytes) return;
  if (kind == "framework") prefault_heap(kFrameworkBytesPerInputByte * input_bytes);
}

}  // namespace kinestat::cli
