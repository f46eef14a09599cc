// SPDX-License-Identifier: BSD-3-Clause
// GMP allocation failures become std::bad_alloc (a clean error) instead of GMP's abort().

#include <gtest/gtest.h>

#include <gmp.h>
#include <sys/resource.h>

#include <cstdint>
#include <cstdlib>
#include <new>

#include "kinestat/address_sanitizer.hpp"
#include "kinestat/linalg/gmp_allocation.hpp"

namespace {

// In a child process: address space capped at 256 MB, then a 1 GB integer is asked for.
// With GMP's own functions this aborts (SIGABRT); with kinestat's it throws std::bad_alloc.
// The child leaves by std::_Exit: std::exit runs OpenBLAS's shutdown, which joins a worker
// thread that may be retrying a 128 MB buffer under the cap forever (seen: a 12-minute hang).
void allocate_beyond_the_limit() {
  rlimit limit{};
  limit.rlim_cur = limit.rlim_max = 256ull << 20;
  if (setrlimit(RLIMIT_AS, &limit) != 0) std::_Exit(5);
  kinestat::linalg::install_throwing_gmp_allocation();
  try {
    mpz_t huge;
    mpz_init2(huge, 8ull << 30);  // 2^33 bits = 1 GB
    mpz_clear(huge);
    std::_Exit(4);
  } catch (const std::bad_alloc&) {
    std::_Exit(3);
  }
}

TEST(GmpAllocationDeathTest, FailureIsACatchableBadAlloc) {
  // AddressSanitizer reserves terabytes of address space for its shadow memory, so a process with
  // RLIMIT_AS capped at 256 MB is killed before main; the capped case runs only without it.
  if (kinestat::kBuiltWithAddressSanitizer) GTEST_SKIP() << "RLIMIT_AS cannot be capped under AddressSanitizer";
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(allocate_beyond_the_limit(), ::testing::ExitedWithCode(3), "");
}

// The installed function itself, asked for more than any machine has: std::bad_alloc, not a null
// pointer GMP would write through. (Runs under ASan too: the preset lets malloc return null.)
TEST(GmpAllocation, ImpossibleRequestThrows) {
  kinestat::linalg::install_throwing_gmp_allocation();
  void* (*allocate)(std::size_t) = nullptr;
  mp_get_memory_functions(&allocate, nullptr, nullptr);
  ASSERT_NE(allocate, nullptr);
  EXPECT_THROW(allocate(SIZE_MAX / 2), std::bad_alloc);
}

TEST(GmpAllocation, OrdinaryArithmeticStillWorks) {
  kinestat::linalg::install_throwing_gmp_allocation();
  mpz_t a;
  mpz_init_set_ui(a, 1);
  mpz_mul_2exp(a, a, 200);  // 2^200 has 61 decimal digits
  EXPECT_EQ(mpz_sizeinbase(a, 10), 61u);
  mpz_clear(a);
}

}  // namespace
