// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// How much memory a sparse factorisation may take, and the refusal of one that would take more.
// SuiteSparseQR's symbolic analysis knows, before any numeric work, the size of the stack of
// frontal matrices that will hold the fronts and R. On graphs without small separators (a random
// network is an expander: every ordering leaves separators proportional to the graph) that
// stack grows with the square of the model: a random network of 3·10⁴ couplings took 11 GB and
// 6 minutes, one of 10⁵ would need far more than a workstation has. Such a factorisation is
// refused after the analysis with what it would need, instead of failing in an allocation
// (or, memory being overcommitted, being killed by the system) later. The limit is the caller's
// option (MemoryLimit, carried by the analysis options down to SparseQr), never process-wide
// state: two analyses in one process may have different limits.

#include <cstdint>

#include "kinestat/error.hpp"

namespace kinestat::linalg {

/// Exit code of a command whose analysis needs more memory than it may have (as for std::bad_alloc).
inline constexpr int kExitTooLarge = 3;

/// A sparse factorisation that needs more memory than it may have: refused after SuiteSparseQR's
/// symbolic analysis predicted more than its MemoryLimit, or stopped when an
/// allocation failed after that analysis (then the analysis's R alone gives a lower bound).
/// what() says how much, why and what to do.
class FactorisationTooLarge : public Error {
 public:
  /// `bytes_needed`: the analysis's figure in bytes (`at_least`: a lower bound); `flops`:
  /// SuiteSparseQR's upper bound on the factorisation's floating-point operations;
  /// `bytes_allowed`: the limit it exceeds, 0 when an allocation failed instead.
  FactorisationTooLarge(double bytes_needed, bool at_least, double flops, double bytes_allowed);

  double bytes_needed() const noexcept { return bytes_needed_; }
  double bytes_allowed() const noexcept { return bytes_allowed_; }
  double flops() const noexcept { return flops_; }

 private:
  double bytes_needed_, bytes_allowed_, flops_;
};

/// The most memory one sparse factorisation may plan to use (SuiteSparseQR's stack of fronts):
/// an option of the caller, passed to SparseQr and sparse_qr_rank by the analyses
/// (framework::AnalysisOptions::memory_limit, network::AnalysisOptions::memory_limit).
struct MemoryLimit {
  std::uint64_t bytes = 0;  ///< bytes; 0: the machine's physical memory
  /// `bytes`, or the machine's physical memory when 0 (no limit when the system does not say).
  std::uint64_t resolved() const;
};

}  // namespace kinestat::linalg
