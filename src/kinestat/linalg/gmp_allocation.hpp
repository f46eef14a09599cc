// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// GMP's default allocation functions call abort() when memory runs out ("GNU MP: Cannot
// allocate memory"), which no caller can catch. These replacements throw std::bad_alloc
// instead, so that exact arithmetic on a model too large for the machine ends as a clean error.

namespace kinestat::linalg {

/// Installs (once per process; later calls do nothing) GMP memory functions that throw
/// std::bad_alloc when an allocation fails. GMP's temporaries of the failing operation leak,
/// which is harmless on the way to exiting.
void install_throwing_gmp_allocation();

}  // namespace kinestat::linalg
