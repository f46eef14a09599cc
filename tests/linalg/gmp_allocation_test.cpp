// GMP allocation failures become std::bad_alloc (a clean error) instead of GMP's abort().

#include <gtest/gtest.h>

#include <gmp.h>
#include <sys/resource.h>

#include <cstdlib>
#include <new>

#include "kinestat/linalg/gmp_allocation.hpp"

namespace {

// In a child process: address space capped at 256 MB, then a 1 GB integer is asked for.
// With GMP's own functions this aborts (SIGABRT); with kinestat's it throws std::bad_alloc.
void allocate_beyond_the_limit() {
  rlimit limit{};
  limit.rlim_cur = limit.rlim_max = 256ull << 20;
  if (setrlimit(RLIMIT_AS, &limit) != 0) std::exit(5);
  kinestat::linalg::install_throwing_gmp_allocation();
  try {
    mpz_t huge;
    mpz_init2(huge, 8ull << 30);  // 2^33 bits = 1 GB
    mpz_clear(huge);
    std::exit(4);
  } catch (const std::bad_alloc&) {
    std::exit(3);
  }
}

TEST(GmpAllocationDeathTest, FailureIsACatchableBadAlloc) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(allocate_beyond_the_limit(), ::testing::ExitedWithCode(3), "");
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
