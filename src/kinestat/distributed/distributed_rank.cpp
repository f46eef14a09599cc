// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/distributed/distributed_rank.hpp"

#include <mpi.h>
#include <petscmat.h>
#include <petscvec.h>
#include <slepceps.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <new>
#include <string>

#include "kinestat/distributed/process_memory.hpp"
#include "kinestat/error.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::distributed {

namespace {

// Exit code of a failure of the numerical libraries (as for internal errors).
constexpr int kExitLibrary = 3;

void check(PetscErrorCode code, const char* what) {
  if (code == 0) return;
  if (code == PETSC_ERR_MEM) throw std::bad_alloc();
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  throw Error(std::string("distributed backend: ") + what + " failed (PETSc error " + std::to_string(code) +
                  (text != nullptr ? std::string(": ") + text : std::string()) + ")",
              {}, kExitLibrary);
}
#define KINESTAT_PETSC_CHECK(call) check((call), #call)

// Owns one PETSc object and destroys it at scope exit.
template <class T, PetscErrorCode (*destroy)(T*)>
struct Owned {
  T object = nullptr;
  Owned() = default;
  Owned(const Owned&) = delete;
  Owned& operator=(const Owned&) = delete;
  ~Owned() {
    if (object != nullptr) destroy(&object);
  }
  T* out() { return &object; }
  operator T() const { return object; }
};
using OwnedMat = Owned<Mat, MatDestroy>;
using OwnedVec = Owned<Vec, VecDestroy>;
using OwnedScatter = Owned<VecScatter, VecScatterDestroy>;
using OwnedEps = Owned<EPS, EPSDestroy>;

// First global row of process `p` of `size` for `total` rows (PETSc's PETSC_DECIDE split).
PetscInt first_row(PetscInt total, int p, int size) {
  const PetscInt base = total / size, extra = total % size;
  return static_cast<PetscInt>(p) * base + std::min<PetscInt>(p, extra);
}

// H = [[0, A], [Aᵀ, 0]] as an MPIAIJ matrix: rank 0 builds its rows (compressed) and scatters
// to every process its block of consecutive rows.
void assemble_jordan_wielandt(const Eigen::SparseMatrix<double>* a, PetscInt m, PetscInt n, int rank, int size,
                              Mat* h) {
  const PetscInt total = m + n;
  std::vector<PetscInt> pointer, column;
  std::vector<PetscScalar> value;
  std::vector<int> row_counts(static_cast<std::size_t>(size)), row_displacements(static_cast<std::size_t>(size));
  std::vector<int> entry_counts(static_cast<std::size_t>(size)), entry_displacements(static_cast<std::size_t>(size));
  for (int p = 0; p < size; ++p) {
    row_displacements[static_cast<std::size_t>(p)] = static_cast<int>(first_row(total, p, size));
    row_counts[static_cast<std::size_t>(p)] = static_cast<int>(first_row(total, p + 1, size) - first_row(total, p, size));
  }
  std::vector<PetscInt> row_lengths;
  if (rank == 0) {
    const Eigen::SparseMatrix<double, Eigen::RowMajor> rows(*a);
    pointer.reserve(static_cast<std::size_t>(total) + 1);
    column.reserve(2 * static_cast<std::size_t>(a->nonZeros()) + static_cast<std::size_t>(total));
    value.reserve(2 * static_cast<std::size_t>(a->nonZeros()) + static_cast<std::size_t>(total));
    pointer.push_back(0);
    // Every row stores its (zero) diagonal entry: PETSc's conversion to MUMPS's symmetric
    // triples expects one.
    for (PetscInt i = 0; i < m; ++i) {
      column.push_back(i);
      value.push_back(0.0);
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(rows, i); it; ++it) {
        column.push_back(m + static_cast<PetscInt>(it.col()));
        value.push_back(it.value());
      }
      pointer.push_back(static_cast<PetscInt>(column.size()));
    }
    for (PetscInt j = 0; j < n; ++j) {
      for (Eigen::SparseMatrix<double>::InnerIterator it(*a, j); it; ++it) {
        column.push_back(static_cast<PetscInt>(it.row()));
        value.push_back(it.value());
      }
      column.push_back(m + j);
      value.push_back(0.0);
      pointer.push_back(static_cast<PetscInt>(column.size()));
    }
    row_lengths.resize(static_cast<std::size_t>(total));
    for (PetscInt i = 0; i < total; ++i) row_lengths[static_cast<std::size_t>(i)] = pointer[static_cast<std::size_t>(i) + 1] - pointer[static_cast<std::size_t>(i)];
    for (int p = 0; p < size; ++p) {
      const auto lo = static_cast<std::size_t>(first_row(total, p, size)), hi = static_cast<std::size_t>(first_row(total, p + 1, size));
      entry_displacements[static_cast<std::size_t>(p)] = static_cast<int>(pointer[lo]);
      entry_counts[static_cast<std::size_t>(p)] = static_cast<int>(pointer[hi] - pointer[lo]);
    }
  }
  const PetscInt local_rows = first_row(total, rank + 1, size) - first_row(total, rank, size);
  std::vector<PetscInt> local_lengths(static_cast<std::size_t>(local_rows));
  MPI_Scatterv(row_lengths.data(), row_counts.data(), row_displacements.data(), MPIU_INT, local_lengths.data(),
               static_cast<int>(local_rows), MPIU_INT, 0, PETSC_COMM_WORLD);
  std::vector<PetscInt> local_pointer(static_cast<std::size_t>(local_rows) + 1, 0);
  for (PetscInt i = 0; i < local_rows; ++i)
    local_pointer[static_cast<std::size_t>(i) + 1] = local_pointer[static_cast<std::size_t>(i)] + local_lengths[static_cast<std::size_t>(i)];
  const auto local_entries = static_cast<std::size_t>(local_pointer.back());
  std::vector<PetscInt> local_column(local_entries);
  std::vector<PetscScalar> local_value(local_entries);
  MPI_Scatterv(column.data(), entry_counts.data(), entry_displacements.data(), MPIU_INT, local_column.data(),
               static_cast<int>(local_entries), MPIU_INT, 0, PETSC_COMM_WORLD);
  MPI_Scatterv(value.data(), entry_counts.data(), entry_displacements.data(), MPIU_SCALAR, local_value.data(),
               static_cast<int>(local_entries), MPIU_SCALAR, 0, PETSC_COMM_WORLD);
  KINESTAT_PETSC_CHECK(MatCreateMPIAIJWithArrays(PETSC_COMM_WORLD, local_rows, local_rows, total, total, local_pointer.data(),
                                                 local_column.data(), local_value.data(), h));
  KINESTAT_PETSC_CHECK(MatSetOption(*h, MAT_SYMMETRIC, PETSC_TRUE));
  KINESTAT_PETSC_CHECK(MatSetOption(*h, MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
}

// Adds the part of `v` orthogonal to the columns of `basis` as a new unit column when it keeps
// more than kRigidMotionZero of v's norm (two passes of Gram–Schmidt).
void extend_basis(Eigen::MatrixXd& basis, Eigen::Index& used, const Eigen::VectorXd& v) {
  const double norm = v.norm();
  if (norm == 0.0) return;
  if (basis.rows() != v.size()) basis.resize(v.size(), 8);
  Eigen::VectorXd w = v / norm;
  for (int pass = 0; pass < 2; ++pass)
    for (Eigen::Index j = 0; j < used; ++j) w -= basis.col(j).dot(w) * basis.col(j);
  const double kept = w.norm();
  if (kept <= kRigidMotionZero) return;
  if (used == basis.cols()) basis.conservativeResize(Eigen::NoChange, std::max<Eigen::Index>(8, 2 * basis.cols()));
  basis.col(used++) = w / kept;
}

// MUMPS's LDLᵀ factorisation of H + shift·I (symmetric indefinite, 2×2 pivots); returns the
// number of negative eigenvalues of H + shift·I (its inertia, INFOG(12)). H's zero diagonal can
// make MUMPS delay pivots beyond the workspace its analysis estimates (INFOG(1) = −9): the
// factorisation is then repeated with 4 times the relaxation (ICNTL(14), %).
PetscInt factor_shifted(Mat h, double shift, Mat* factor, DistributedRank& result) {
  KINESTAT_PETSC_CHECK(MatShift(h, shift));
  PetscInt status = 0;
  for (int relaxation = 100;; relaxation *= 4) {
    KINESTAT_PETSC_CHECK(PetscOptionsSetValue(nullptr, "-mat_mumps_icntl_14", std::to_string(relaxation).c_str()));
    if (*factor != nullptr) KINESTAT_PETSC_CHECK(MatDestroy(factor));
    KINESTAT_PETSC_CHECK(MatGetFactor(h, MATSOLVERMUMPS, MAT_FACTOR_CHOLESKY, factor));
    MatFactorInfo info;
    KINESTAT_PETSC_CHECK(MatFactorInfoInitialize(&info));
    KINESTAT_PETSC_CHECK(MatCholeskyFactorSymbolic(*factor, h, nullptr, &info));
    KINESTAT_PETSC_CHECK(MatCholeskyFactorNumeric(*factor, h, &info));
    KINESTAT_PETSC_CHECK(MatMumpsGetInfog(*factor, 1, &status));
    if (status != -9 || relaxation >= 6400) break;
  }
  KINESTAT_PETSC_CHECK(MatShift(h, -shift));
  if (status == -9 || status == -13) throw std::bad_alloc();
  if (status < 0) throw Error("distributed backend: MUMPS failed with INFOG(1) = " + std::to_string(status), {}, kExitLibrary);
  PetscInt negative = 0, megabytes_max = 0, megabytes_total = 0;
  KINESTAT_PETSC_CHECK(MatGetInertia(*factor, &negative, nullptr, nullptr));
  KINESTAT_PETSC_CHECK(MatMumpsGetInfog(*factor, 21, &megabytes_max));
  KINESTAT_PETSC_CHECK(MatMumpsGetInfog(*factor, 22, &megabytes_total));
  result.factor_megabytes_max = std::max<long long>(result.factor_megabytes_max, megabytes_max);
  result.factor_megabytes_total = std::max<long long>(result.factor_megabytes_total, megabytes_total);
  return negative;
}

// MUMPS's parallel factorisation and solves sum in the order messages arrive, so that with
// P ≥ 2 the null vectors differ from run to run in their last bits. What rank 0 reports is made
// repeatable: every entry of a vector is rounded to a multiple of kDistributedVectorGrid of the
// vector's largest (entries equal but for that noise, as in a symmetric model, become equal,
// so ties are broken alike; the residual this adds, about 10⁻¹³ σ_max, stays below the
// threshold); residuals are upper bounds at the report floor (distributed_report_bound), and
// singular values are rounded to the digits their residual guarantees (distributed_round_to).
void distributed_round_entries(Eigen::Ref<Eigen::VectorXd> v) {
  const double largest = v.cwiseAbs().maxCoeff();
  if (largest == 0.0) return;
  const double unit = largest * kDistributedVectorGrid;
  for (Eigen::Index i = 0; i < v.size(); ++i) v(i) = std::round(v(i) / unit) * unit;
}

// A power of ten as the nearest double (10^k for k < 0 as 1 / 10^−k, which prints as "1e-13").
double distributed_power_of_ten(int exponent) {
  return exponent >= 0 ? std::pow(10.0, exponent) : 1.0 / std::pow(10.0, -exponent);
}

// `value` rounded to the nearest multiple of the power of ten at or above `error` (> 0, the
// absolute error the value is known to): a singular value from an eigenpair of H whose residual
// is at most `error` lies within `error` of one of H's eigenvalues, so these are the digits the
// computation guarantees, and the last-bit noise of P ≥ 2 (about ε σ_max) changes them only on
// a rounding boundary. At least one significant digit is kept (a value is never rounded to 0,
// which the report reads as "not computed"), even when `error` exceeds it.
double distributed_round_to(double value, double error) {
  if (value == 0.0 || !std::isfinite(value) || !(error > 0.0) || !std::isfinite(error)) return value;
  const int exponent = std::min(static_cast<int>(std::ceil(std::log10(error))),
                                static_cast<int>(std::floor(std::log10(std::abs(value)))));
  if (exponent >= 0) {
    const double unit = std::pow(10.0, exponent);
    return std::round(value / unit) * unit;
  }
  const double scale = std::pow(10.0, -exponent);
  return std::round(value * scale) / scale;
}

// A pseudo-random number in [−1, 1) for entry `index` of draw `draw` (splitmix64): the same
// on any number of processes.
double pseudo_random(std::uint64_t index, std::uint64_t draw) {
  std::uint64_t x = index * 0x9E3779B97F4A7C15ULL + (draw + 1) * 0xD1B54A32D192ED03ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  x ^= x >> 31;
  return static_cast<double>(x >> 11) * 0x1p-52 - 1.0;
}

// Destroys every vector of a list when its scope ends (vectors from MUMPS and SLEPc solves).
struct DistributedVecsRelease {
  std::vector<Vec>& vectors;
  ~DistributedVecsRelease() {
    for (Vec& v : vectors) VecDestroy(&v);
  }
};

// The start vector of every SLEPc solve here, fixed (as the serial power iteration's) so that
// every run gives the same answer: 1 + sin(i + 1) / 2 for global row i.
void set_fixed_start(EPS eps, Mat h, OwnedVec& start) {
  KINESTAT_PETSC_CHECK(MatCreateVecs(h, start.out(), nullptr));
  PetscInt lo = 0, hi = 0;
  KINESTAT_PETSC_CHECK(VecGetOwnershipRange(start, &lo, &hi));
  PetscScalar* entries = nullptr;
  KINESTAT_PETSC_CHECK(VecGetArray(start, &entries));
  for (PetscInt i = lo; i < hi; ++i) entries[i - lo] = 1.0 + 0.5 * std::sin(static_cast<double>(i) + 1.0);
  KINESTAT_PETSC_CHECK(VecRestoreArray(start, &entries));
  Vec initial[1] = {start};
  KINESTAT_PETSC_CHECK(EPSSetInitialSpace(eps, 1, initial));
}

// y = (MUMPS's solve with H)·x: the shell operator whose largest eigenvalues are 1/σ_r.
PetscErrorCode apply_solve(Mat shell, Vec x, Vec y) {
  Mat* factor = nullptr;
  PetscCall(MatShellGetContext(shell, &factor));
  PetscCall(MatSolve(*factor, x, y));
  return 0;
}

// The smallest kept singular value: the largest-magnitude eigenvalues μ of the solve operator
// G (G u = u/λ + null part for every eigenpair (λ, u) of H with λ ≠ 0), each checked on H
// itself: u = μ H w for G's eigenvector w, accepted when ‖H u − u/μ‖ ≤ kDistributedSingularResidual
// σ_max ‖u‖. The smallest accepted |1/μ|.
void smallest_kept(Mat h, Mat factor, double shift, std::vector<Vec>& null_space, double largest, DistributedRank& result) {
  PetscInt local = 0, global = 0;
  KINESTAT_PETSC_CHECK(MatGetLocalSize(h, &local, nullptr));
  KINESTAT_PETSC_CHECK(MatGetSize(h, &global, nullptr));
  OwnedMat shell;
  Mat context = factor;
  KINESTAT_PETSC_CHECK(MatCreateShell(PETSC_COMM_WORLD, local, local, global, global, &context, shell.out()));
  KINESTAT_PETSC_CHECK(MatShellSetOperation(shell, MATOP_MULT, reinterpret_cast<void (*)(void)>(apply_solve)));
  OwnedEps eps;
  KINESTAT_PETSC_CHECK(EPSCreate(PETSC_COMM_WORLD, eps.out()));
  KINESTAT_PETSC_CHECK(EPSSetOperators(eps, shell, nullptr));
  KINESTAT_PETSC_CHECK(EPSSetProblemType(eps, EPS_HEP));
  if (!null_space.empty())
    KINESTAT_PETSC_CHECK(EPSSetDeflationSpace(eps, static_cast<PetscInt>(null_space.size()), null_space.data()));
  KINESTAT_PETSC_CHECK(EPSSetType(eps, EPSKRYLOVSCHUR));
  KINESTAT_PETSC_CHECK(EPSSetWhichEigenpairs(eps, EPS_LARGEST_MAGNITUDE));
  KINESTAT_PETSC_CHECK(EPSSetDimensions(eps, 2, PETSC_DEFAULT, PETSC_DEFAULT));
  KINESTAT_PETSC_CHECK(EPSSetTolerances(eps, kDistributedSmallestTolerance, kDistributedSmallestIterations));
  OwnedVec start, w, u, residual;
  set_fixed_start(eps, h, start);
  KINESTAT_PETSC_CHECK(EPSSolve(eps));
  PetscInt converged = 0;
  KINESTAT_PETSC_CHECK(EPSGetConverged(eps, &converged));
  KINESTAT_PETSC_CHECK(MatCreateVecs(h, w.out(), u.out()));
  KINESTAT_PETSC_CHECK(VecDuplicate(u, residual.out()));
  double best = 0.0, best_residual = 0.0;
  for (PetscInt i = 0; i < converged; ++i) {
    PetscScalar real = 0.0, imaginary = 0.0;
    KINESTAT_PETSC_CHECK(EPSGetEigenpair(eps, i, &real, &imaginary, w, nullptr));
    if (imaginary != 0.0 || real == 0.0) continue;
    const double lambda = 1.0 / real - shift;  // μ = 1 / (λ + t)
    KINESTAT_PETSC_CHECK(VecCopy(w, u));
    KINESTAT_PETSC_CHECK(MatMult(h, u, residual));
    KINESTAT_PETSC_CHECK(VecAXPY(residual, -lambda, u));
    PetscReal r = 0.0, norm = 0.0;
    KINESTAT_PETSC_CHECK(VecNorm(residual, NORM_2, &r));
    KINESTAT_PETSC_CHECK(VecNorm(u, NORM_2, &norm));
    if (norm == 0.0) continue;
    const double relative = r / (largest * norm);
    if (relative > kDistributedSingularResidual) continue;
    if (best == 0.0 || std::abs(lambda) < best) {
      best = std::abs(lambda);
      best_residual = relative;
    }
  }
  result.smallest_kept_verified = best > 0.0;
  if (best > 0.0) {
    result.smallest_kept_residual = distributed_report_bound(best_residual, result.report_floor);
    result.decision.smallest_kept = distributed_round_to(best, result.smallest_kept_residual * largest);
  }
}

// y = (s·(H + s·I)⁻¹ − I)·x through MUMPS's solve: the operator whose positive eigenvalues are
// σ/(s − σ) for the singular values σ < s of A (eigenvalue −σ of H), 0 for H's null space,
// −σ/(s + σ) ∈ (−1, 0) for +σ and below −1 for −σ with σ > s.
struct DistributedWindowOperator {
  Mat factor = nullptr;
  double shift = 0.0;
};

PetscErrorCode apply_window_operator(Mat shell, Vec x, Vec y) {
  DistributedWindowOperator* op = nullptr;
  PetscCall(MatShellGetContext(shell, &op));
  PetscCall(MatSolve(op->factor, x, y));
  PetscCall(VecScale(y, op->shift));
  PetscCall(VecAXPY(y, -1.0, x));
  return 0;
}

// One eigenpair of H found through the window operator and checked on H itself: w a unit
// vector, λ = wᵀ H w, residual ‖H w − λ w‖ / σ_max.
struct DistributedWindowPair {
  double lambda = 0.0, residual = 0.0;
  Vec vector = nullptr;  // owned by the caller's list
};

// The `count` eigenpairs of the window operator at the end `which` of its spectrum (SLEPc's
// Krylov–Schur, absolute tolerance kDistributedWindowTolerance on the operator, whose spectrum
// lies in [−1, ∞) but for σ near s), each checked on H. The vectors are appended to `owned`.
std::vector<DistributedWindowPair> window_pairs(Mat h, Mat factor, double shift, EPSWhich which, PetscInt count,
                                                double largest, std::vector<Vec>& owned) {
  PetscInt local = 0, global = 0;
  KINESTAT_PETSC_CHECK(MatGetLocalSize(h, &local, nullptr));
  KINESTAT_PETSC_CHECK(MatGetSize(h, &global, nullptr));
  DistributedWindowOperator op{factor, shift};
  OwnedMat shell;
  KINESTAT_PETSC_CHECK(MatCreateShell(PETSC_COMM_WORLD, local, local, global, global, &op, shell.out()));
  KINESTAT_PETSC_CHECK(MatShellSetOperation(shell, MATOP_MULT, reinterpret_cast<void (*)(void)>(apply_window_operator)));
  OwnedEps eps;
  KINESTAT_PETSC_CHECK(EPSCreate(PETSC_COMM_WORLD, eps.out()));
  KINESTAT_PETSC_CHECK(EPSSetOperators(eps, shell, nullptr));
  KINESTAT_PETSC_CHECK(EPSSetProblemType(eps, EPS_HEP));
  KINESTAT_PETSC_CHECK(EPSSetType(eps, EPSKRYLOVSCHUR));
  KINESTAT_PETSC_CHECK(EPSSetWhichEigenpairs(eps, which));
  KINESTAT_PETSC_CHECK(EPSSetDimensions(eps, std::min(count, global), PETSC_DEFAULT, PETSC_DEFAULT));
  KINESTAT_PETSC_CHECK(EPSSetConvergenceTest(eps, EPS_CONV_ABS));
  KINESTAT_PETSC_CHECK(EPSSetTolerances(eps, kDistributedWindowTolerance, kDistributedWindowIterations));
  OwnedVec start, hw, residual;
  set_fixed_start(eps, h, start);
  KINESTAT_PETSC_CHECK(EPSSolve(eps));
  PetscInt converged = 0;
  KINESTAT_PETSC_CHECK(EPSGetConverged(eps, &converged));
  KINESTAT_PETSC_CHECK(VecDuplicate(start, hw.out()));
  KINESTAT_PETSC_CHECK(VecDuplicate(start, residual.out()));
  std::vector<DistributedWindowPair> pairs;
  for (PetscInt i = 0; i < converged; ++i) {
    PetscScalar real = 0.0, imaginary = 0.0;
    Vec w = nullptr;
    KINESTAT_PETSC_CHECK(VecDuplicate(start, &w));
    owned.push_back(w);
    KINESTAT_PETSC_CHECK(EPSGetEigenpair(eps, i, &real, &imaginary, w, nullptr));
    PetscReal norm = 0.0;
    KINESTAT_PETSC_CHECK(VecNormalize(w, &norm));
    if (imaginary != 0.0 || norm == 0.0) continue;
    KINESTAT_PETSC_CHECK(MatMult(h, w, hw));
    PetscScalar lambda = 0.0;
    KINESTAT_PETSC_CHECK(VecDot(hw, w, &lambda));
    KINESTAT_PETSC_CHECK(VecWAXPY(residual, -lambda, w, hw));
    PetscReal r = 0.0;
    KINESTAT_PETSC_CHECK(VecNorm(residual, NORM_2, &r));
    pairs.push_back({lambda, r / largest, w});
  }
  return pairs;
}

}  // namespace

double distributed_report_bound(double relative, double floor) {
  if (!std::isfinite(relative) || relative < 0.0) return relative;
  const double above = relative > 0.0 ? distributed_power_of_ten(static_cast<int>(std::ceil(std::log10(relative)))) : 0.0;
  return std::max(above, floor);
}

DistributedRank distributed_rank(const Eigen::SparseMatrix<double>* a, const linalg::RankDecision& threshold,
                                 const DistributedRankOptions& options) {
  DistributedRank result;
  int rank = 0, size = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  result.processes = size;
  long long dims[2] = {0, 0};
  double values[4] = {0.0, 0.0, 0.0, 0.0};
  if (rank == 0) {
    dims[0] = a->rows();
    dims[1] = a->cols();
    values[0] = threshold.largest;
    values[1] = threshold.threshold;
    values[2] = threshold.rounding_level;
    values[3] = threshold.input_rounding;
  }
  MPI_Bcast(dims, 2, MPI_LONG_LONG, 0, PETSC_COMM_WORLD);
  MPI_Bcast(values, 4, MPI_DOUBLE, 0, PETSC_COMM_WORLD);
  const auto m = static_cast<PetscInt>(dims[0]), n = static_cast<PetscInt>(dims[1]);
  if (dims[0] + dims[1] > 0x7fffffffLL)
    throw Error("distributed backend: the matrix has more than 2^31 rows and columns, beyond this PETSc's 32-bit indices", {},
                kExitLibrary);
  linalg::RankDecision& d = result.decision;
  d.rows = m;
  d.cols = n;
  d.sparse = true;
  d.largest = values[0];
  d.threshold = values[1];
  d.rounding_level = values[2];
  d.input_rounding = values[3];
  if (d.largest > 0.0 && d.threshold > 0.0)
    result.report_floor =
        distributed_power_of_ten(static_cast<int>(std::floor(std::log10(kDistributedReportFloor * d.threshold / d.largest))));
  auto gather_memory = [&] {
    unsigned long long mine = peak_resident_bytes();
    std::vector<unsigned long long> all(static_cast<std::size_t>(size));
    MPI_Gather(&mine, 1, MPI_UNSIGNED_LONG_LONG, all.data(), 1, MPI_UNSIGNED_LONG_LONG, 0, PETSC_COMM_WORLD);
    if (rank == 0) result.peak_memory.assign(all.begin(), all.end());
  };
  if (m == 0 || n == 0 || d.largest == 0.0) {  // nothing to factor: rank 0
    gather_memory();
    return result;
  }

  double clock = MPI_Wtime();
  OwnedMat h;
  assemble_jordan_wielandt(a, m, n, rank, size, h.out());
  result.assembly_seconds = MPI_Wtime() - clock;

  // The rank by Sylvester's law of inertia: H's eigenvalues are ±σ_i and zeros, so H + s·I has
  // exactly one negative eigenvalue per σ_i > s: rank = the negative pivots of its LDLᵀ. The
  // shift is s = kCertainMargin·t, not the threshold t itself: the indefinite LDLᵀ's backward
  // error exceeds the sparse rule's t (measured: a 12 390-bar cubic lattice counts 14 zero
  // eigenvalues of H as negative at s = t, none at 100 t), so the count at t is not resolved. It
  // equals the rank at t unless a singular value lies in (t, 100 t], the zone where the serial
  // sparse decision is itself close. The count at kCertainMargin²·t says whether one lies in
  // (100 t, 10⁴ t]. ScaLAPACK is off at the root (MUMPS reports the inertia only then).
  clock = MPI_Wtime();
  KINESTAT_PETSC_CHECK(PetscOptionsSetValue(nullptr, "-mat_mumps_icntl_13", "1"));
  // The ordering on the graph compressed by MUMPS's 2×2 pivots from a maximum weighted matching
  // (ICNTL(12) = 2, meant for augmented systems with zero diagonal): 20 times faster on a
  // 10⁴-bar triangulated grid than the default, which delays pivot after pivot.
  KINESTAT_PETSC_CHECK(PetscOptionsSetValue(nullptr, "-mat_mumps_icntl_12", "2"));
  const double t = kCertainMargin * d.threshold;
  result.shift = t;
  OwnedMat factor;
  d.rank = factor_shifted(h, t, factor.out(), result);
  {
    OwnedMat other;
    result.rank_above_margin = factor_shifted(h, kCertainMargin * t, other.out(), result);
  }
  result.factor_seconds = MPI_Wtime() - clock;

  // The window (t, s]: the serial rule keeps a singular value above t, the inertia at s counts
  // it as null. The positive eigenvalues of the window operator s·(H + s·I)⁻¹ − I are
  // σ/(s − σ) for the singular values σ < s (eigenvalue −σ of H) and 0 on H's null space, so its
  // largest ones, each checked on H itself (Rayleigh quotient λ = wᵀ H w, residual), are those
  // of the window first, then values at or below t: once one of those is found, the window has
  // been searched whole. The rank at t is the inertia's count plus the window's.
  clock = MPI_Wtime();
  std::vector<Vec> window_owned;  // every vector SLEPc returned
  const DistributedVecsRelease release_window{window_owned};
  double window_smallest = 0.0;
  if (options.window && d.rank < std::min<Eigen::Index>(m, n)) {
    for (PetscInt count = kDistributedWindowBatch;; count *= 4) {
      for (Vec& v : window_owned) VecDestroy(&v);
      window_owned.clear();
      result.window_kept = 0;
      result.window_residual = 0.0;
      result.window_searched = false;
      window_smallest = 0.0;
      for (const DistributedWindowPair& pair : window_pairs(h, factor, t, EPS_LARGEST_REAL, count, d.largest, window_owned)) {
        if (pair.residual > kDistributedSingularResidual) continue;
        const double sigma = -pair.lambda;
        if (sigma > d.threshold && sigma <= t) {
          ++result.window_kept;
          result.window_residual = std::max(result.window_residual, pair.residual);
          window_smallest = window_smallest == 0.0 ? sigma : std::min(window_smallest, sigma);
        } else if (sigma <= d.threshold) {
          result.window_searched = true;
        }
      }
      if (result.window_searched || count >= kDistributedWindowMostPairs) break;
    }
    d.rank += result.window_kept;
    if (result.window_kept > 0) result.window_residual = distributed_report_bound(result.window_residual, result.report_floor);
  }
  result.window_seconds = MPI_Wtime() - clock;
  result.null_pivots = static_cast<Eigen::Index>(m) + n - 2 * d.rank;
  const PetscInt null_pivots = static_cast<PetscInt>(result.null_pivots);

  // Null vectors of H by two steps of inverse iteration, v = (H + s·I)⁻² z for a fixed
  // pseudo-random z: a dropped direction grows by 1/s per step, a kept one by at most
  // 1/(σ_r − s). z is random in one block, A's columns (aiming at a mechanism) or its rows (a
  // self-stress); the parts of v are a null vector of Aᵀ (first m entries) and of A (last n).
  clock = MPI_Wtime();
  const bool whole = null_pivots <= options.full_basis_limit;
  const Eigen::Index mechanisms = n - d.rank, stresses = m - d.rank;
  const Eigen::Index want_mechanisms = whole ? mechanisms : std::min(options.vectors, mechanisms);
  const Eigen::Index want_stresses = whole ? stresses : std::min(options.vectors, stresses);
  // Generic vectors: the first `generic_vectors` draws in each block whose null space is not empty.
  const Eigen::Index want_generic = std::max<Eigen::Index>(options.generic_vectors, 0);
  Eigen::MatrixXd stress_basis, mechanism_basis;
  Eigen::Index stress_used = 0, mechanism_used = 0, generic_mechanisms = 0, generic_stresses = 0;
  if (rank == 0 && want_generic > 0) {
    result.generic_mechanisms.resize(n, mechanisms > 0 ? want_generic : 0);
    result.generic_self_stresses.resize(m, stresses > 0 ? want_generic : 0);
  }
  // Whether a draw in block 1 (A's columns: mechanisms) or 2 (its rows: self-stresses) is still wanted.
  auto need_mechanism = [&] {
    return mechanism_used < want_mechanisms || generic_mechanisms < result.generic_mechanisms.cols();
  };
  auto need_stress = [&] { return stress_used < want_stresses || generic_stresses < result.generic_self_stresses.cols(); };
  std::vector<Vec> null_space;  // the vectors computed, kept for SLEPc's deflation when whole
  const DistributedVecsRelease release{null_space};
  int block = rank == 0 ? (need_mechanism() ? 1 : need_stress() ? 2 : 0) : 0;
  MPI_Bcast(&block, 1, MPI_INT, 0, PETSC_COMM_WORLD);
  OwnedVec x, gathered;
  OwnedScatter to_root;
  KINESTAT_PETSC_CHECK(MatCreateVecs(h, nullptr, x.out()));
  KINESTAT_PETSC_CHECK(VecScatterCreateToZero(x, to_root.out(), gathered.out()));
  // A kept singular value in (s, kCertainMargin·s] (the two inertia counts differ) is barely
  // separated from the null space at the shift s: each step of inverse iteration or refinement
  // shrinks its part only by s/σ. The vectors then come from a factor at the threshold t = s /
  // kCertainMargin (a third factorisation, whose inertia is not used): kCertainMargin times the
  // separation per step, the refinement removing its larger backward error. Measured: the
  // generated ladders of 1 300 to 3 000 couplings, residuals 10⁻⁸ to 10⁻⁶ at s, 10⁻¹⁶ at t.
  OwnedMat near_factor;
  Mat solver = factor;
  if (block != 0 && result.rank_above_margin != d.rank) {
    factor_shifted(h, d.threshold, near_factor.out(), result);
    solver = near_factor;
    result.vectors_at_threshold = true;
  }
  if (block != 0) {
    OwnedVec z, hz, hx;
    KINESTAT_PETSC_CHECK(VecDuplicate(x, z.out()));
    KINESTAT_PETSC_CHECK(VecDuplicate(x, hx.out()));
    KINESTAT_PETSC_CHECK(VecDuplicate(x, hz.out()));
    PetscInt lo = 0, hi = 0;
    KINESTAT_PETSC_CHECK(VecGetOwnershipRange(z, &lo, &hi));
    const long long attempts = 2LL * (want_mechanisms + want_stresses + 2 * want_generic) + 8;
    for (long long draw = 0; draw < attempts && block != 0; ++draw) {
      PetscScalar* entries = nullptr;
      KINESTAT_PETSC_CHECK(VecGetArray(z, &entries));
      for (PetscInt g = lo; g < hi; ++g) {
        const bool in_block = block == 1 ? g >= m : g < m;
        entries[g - lo] = in_block ? pseudo_random(static_cast<std::uint64_t>(g), static_cast<std::uint64_t>(draw)) : 0.0;
      }
      KINESTAT_PETSC_CHECK(VecRestoreArray(z, &entries));
      KINESTAT_PETSC_CHECK(MatSolve(solver, z, hz));
      KINESTAT_PETSC_CHECK(VecNormalize(hz, nullptr));
      KINESTAT_PETSC_CHECK(MatSolve(solver, hz, x));
      KINESTAT_PETSC_CHECK(VecNormalize(x, nullptr));
      // Refinement: x ← x − (H + s·I)⁻¹ H x removes what is left of x along a kept singular
      // vector (factor s/(σ + s) per step, as an inverse iteration step), but from the residual
      // H x formed with H itself, so that the LDLᵀ's backward error enters only the small
      // correction: a null vector of H + E with ‖E‖ that error (inverse iteration's limit, an
      // error of ‖E‖/σ_r in x) becomes one of H. Without it the supports of the generic vectors
      // of a 10³-coupling network spread over every coupling.
      for (int step = 0; step < kDistributedRefinementSteps; ++step) {
        KINESTAT_PETSC_CHECK(MatMult(h, x, hx));
        KINESTAT_PETSC_CHECK(MatSolve(solver, hx, hz));
        KINESTAT_PETSC_CHECK(VecAXPY(x, -1.0, hz));
        KINESTAT_PETSC_CHECK(VecNormalize(x, nullptr));
      }
      KINESTAT_PETSC_CHECK(MatMult(h, x, hx));
      PetscReal norm = 0.0, residual = 0.0;
      KINESTAT_PETSC_CHECK(VecNorm(x, NORM_2, &norm));
      KINESTAT_PETSC_CHECK(VecNorm(hx, NORM_2, &residual));
      if (norm > 0.0) result.null_vector_residual = std::max(result.null_vector_residual, residual / (d.largest * norm));
      ++result.null_vectors_computed;
      KINESTAT_PETSC_CHECK(VecScatterBegin(to_root, x, gathered, INSERT_VALUES, SCATTER_FORWARD));
      KINESTAT_PETSC_CHECK(VecScatterEnd(to_root, x, gathered, INSERT_VALUES, SCATTER_FORWARD));
      if (rank == 0) {
        const PetscScalar* values_read = nullptr;
        KINESTAT_PETSC_CHECK(VecGetArrayRead(gathered, &values_read));
        const Eigen::Map<const Eigen::VectorXd> v(values_read, m + n);
        // A part below kTangentKept of the vector is rounding of the other part, not a direction.
        const double kept = kTangentKept * v.norm();
        // The first vectors from a start in each block, as they are: generic in that null space.
        if (block == 1 && generic_mechanisms < result.generic_mechanisms.cols() && v.tail(n).norm() > kept)
          result.generic_mechanisms.col(generic_mechanisms++) = v.tail(n).normalized();
        if (block == 2 && generic_stresses < result.generic_self_stresses.cols() && v.head(m).norm() > kept)
          result.generic_self_stresses.col(generic_stresses++) = v.head(m).normalized();
        if (stress_used < want_stresses && v.head(m).norm() > kept) extend_basis(stress_basis, stress_used, v.head(m));
        if (mechanism_used < want_mechanisms && v.tail(n).norm() > kept)
          extend_basis(mechanism_basis, mechanism_used, v.tail(n));
        KINESTAT_PETSC_CHECK(VecRestoreArrayRead(gathered, &values_read));
        block = need_mechanism() && (draw % 2 == 1 || !need_stress()) ? 1 : need_stress() ? 2 : need_mechanism() ? 1 : 0;
      }
      MPI_Bcast(&block, 1, MPI_INT, 0, PETSC_COMM_WORLD);
    }
  }
  if (rank == 0) {
    stress_basis.conservativeResize(m, stress_used);
    mechanism_basis.conservativeResize(n, mechanism_used);
    // The whole null space: H has null_pivots eigenvalues within ‖H Q‖_F, Q = diag(Q_s, Q_m)
    // orthonormal (Courant–Fischer), so the largest dropped singular value is at most that.
    if (whole && stress_used == stresses && mechanism_used == mechanisms) {
      double squared = 0.0;
      for (Eigen::Index j = 0; j < mechanism_used; ++j) squared += ((*a) * mechanism_basis.col(j)).squaredNorm();
      for (Eigen::Index j = 0; j < stress_used; ++j) squared += (a->transpose() * stress_basis.col(j)).squaredNorm();
      // Reported as an upper bound at the report floor, as the residuals: its value is rounding.
      d.largest_dropped = distributed_report_bound(std::sqrt(squared) / d.largest, result.report_floor) * d.largest;
      result.dropped_bounded = true;
    }
    result.mechanisms = mechanism_basis.leftCols(std::min(options.vectors, mechanism_used));
    result.self_stresses = stress_basis.leftCols(std::min(options.vectors, stress_used));
    for (Eigen::Index j = 0; j < result.mechanisms.cols(); ++j) {
      distributed_round_entries(result.mechanisms.col(j));
      const double norm = result.mechanisms.col(j).norm();
      result.mechanism_residuals.push_back(
          distributed_report_bound(((*a) * result.mechanisms.col(j)).norm() / (d.largest * norm), result.report_floor));
    }
    for (Eigen::Index j = 0; j < result.self_stresses.cols(); ++j) {
      distributed_round_entries(result.self_stresses.col(j));
      const double norm = result.self_stresses.col(j).norm();
      result.self_stress_residuals.push_back(
          distributed_report_bound((a->transpose() * result.self_stresses.col(j)).norm() / (d.largest * norm), result.report_floor));
    }
    // Draws that left no vector (attempts ran out) leave no column.
    result.generic_mechanisms.conservativeResize(n, generic_mechanisms);
    result.generic_self_stresses.conservativeResize(m, generic_stresses);
    for (Eigen::Index j = 0; j < generic_mechanisms; ++j) distributed_round_entries(result.generic_mechanisms.col(j));
    for (Eigen::Index j = 0; j < generic_stresses; ++j) distributed_round_entries(result.generic_self_stresses.col(j));
    if (result.null_vectors_computed > 0)
      result.null_vector_residual = distributed_report_bound(result.null_vector_residual, result.report_floor);
  }
  result.vector_seconds = MPI_Wtime() - clock;

  clock = MPI_Wtime();
  int complete = rank == 0 ? (result.dropped_bounded ? 1 : 0) : 0;
  MPI_Bcast(&complete, 1, MPI_INT, 0, PETSC_COMM_WORLD);
  // A value kept in the window is the smallest kept one (every other kept value exceeds s).
  if (result.window_kept > 0) {
    result.smallest_kept_verified = true;
    result.smallest_kept_residual = result.window_residual;  // already the reported bound
    d.smallest_kept = distributed_round_to(window_smallest, result.smallest_kept_residual * d.largest);
  }
  const bool search_kept = options.smallest_kept && d.rank > 0 && result.window_kept == 0;
  if (complete == 1 && search_kept) {
    // The orthonormal null space of H, diag(Q_s, Q_m), as distributed vectors for SLEPc.
    long long count[2] = {stress_used, mechanism_used};
    MPI_Bcast(count, 2, MPI_LONG_LONG, 0, PETSC_COMM_WORLD);
    for (int part = 0; part < 2; ++part) {
      for (long long j = 0; j < count[part]; ++j) {
        if (rank == 0) {
          PetscScalar* entries = nullptr;
          KINESTAT_PETSC_CHECK(VecGetArray(gathered, &entries));
          Eigen::Map<Eigen::VectorXd> v(entries, m + n);
          v.setZero();
          if (part == 0) v.head(m) = stress_basis.col(j);
          else v.tail(n) = mechanism_basis.col(j);
          KINESTAT_PETSC_CHECK(VecRestoreArray(gathered, &entries));
        }
        Vec spread = nullptr;
        KINESTAT_PETSC_CHECK(VecDuplicate(x, &spread));
        null_space.push_back(spread);
        KINESTAT_PETSC_CHECK(VecScatterBegin(to_root, gathered, spread, INSERT_VALUES, SCATTER_REVERSE));
        KINESTAT_PETSC_CHECK(VecScatterEnd(to_root, gathered, spread, INSERT_VALUES, SCATTER_REVERSE));
      }
    }
  }
  if (search_kept && complete == 1) {
    smallest_kept(h, factor, t, null_space, d.largest, result);
  } else if (search_kept && options.window) {
    // The null space is not whole: the most negative eigenvalue of the window operator,
    // s/(s − σ) − 1 for the smallest σ above s (eigenvalue −σ of H), checked on H.
    std::vector<Vec> owned;
    const DistributedVecsRelease release_owned{owned};
    double best = 0.0, best_residual = 0.0;
    for (const DistributedWindowPair& pair : window_pairs(h, factor, t, EPS_SMALLEST_REAL, 1, d.largest, owned)) {
      const double sigma = -pair.lambda;
      if (pair.residual > kDistributedSingularResidual || !(sigma > t)) continue;
      if (best == 0.0 || sigma < best) {
        best = sigma;
        best_residual = pair.residual;
      }
    }
    result.smallest_kept_verified = best > 0.0;
    if (best > 0.0) {
      result.smallest_kept_residual = distributed_report_bound(best_residual, result.report_floor);
      d.smallest_kept = distributed_round_to(best, result.smallest_kept_residual * d.largest);
    }
  }
  result.evidence_seconds = MPI_Wtime() - clock;
  gather_memory();
  return result;
}

}  // namespace kinestat::distributed
