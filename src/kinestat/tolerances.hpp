// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Every tolerance kinestat uses, in one place (docs/architecture.md, sections "Tolerances" and "Rank decisions", explains each).
//
// All are relative and dimensionless, so no answer changes with the unit of length. Those that
// judge rounding are written as 2^k ε, ε the double-precision machine epsilon (2.2e-16): "a
// quantity this small may be k bits of rounding". The others are ratios that say how clear a
// decision must be to be called clear. A user's `--tolerance` (Tolerances::rank) reaches every
// rank decision: the rank of the main matrix, the freedoms of each pair of bodies, and the
// choice of free (primary) variables.

#include <limits>
#include <optional>

namespace kinestat {

/// Double-precision machine epsilon, 2^-52 ≈ 2.22e-16.
inline constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// --- Rank decisions --------------------------------------------------------------------------

/// A floating-point rank decision is certain when its smallest kept singular value is at least
/// this many times the proven error bound of the computed singular values
/// (linalg::singular_value_error_bound) and every dropped value is within that bound; otherwise
/// it is close. Two decades of margin over a bound whose constant is taken as 1. A sparse QR
/// decision whose smallest kept |R_ii| is below this many times its threshold is close.
inline constexpr double kCertainMargin = 100.0;
/// A rank decision whose smallest kept singular value is below this fraction of the largest is
/// near a rank change: a relative change of the design this small gives one more motion and one
/// more self-stress, and the verdict says so ("exactly constrained, but 1e-09 from a mechanism").
/// A micrometre in a metre: below what manufacture holds.
inline constexpr double kNearRankChange = 1e-6;
/// The rank threshold rises with the rounding of the input itself: coordinates written at full
/// precision carry an error of ε × their magnitude, so a model far from the origin (a 10 mm
/// flexure 1 m from the machine origin) is special only to within ε × offset / size, and the
/// computed singular value of a special design is of that order (0.1 to 0.9 of it measured on
/// rotated and translated examples). The default threshold is max(m, n) · max(ε, this factor ×
/// that input rounding level), so placement never changes the answer and a model near the
/// origin keeps about the LAPACK rule.
inline constexpr double kInputRoundingFactor = 2.0;
/// Sparse QR ranks: the threshold is this factor × (rows + cols) · ε · the largest column norm
/// (SuiteSparseQR's own default rule uses 20 · (rows + cols) · ε · max column norm).
inline constexpr double kSparseToleranceFactor = 20.0;
/// Pair and coupling systems of a network are ranked against the size of the whole network's
/// forms, not their own, so a pair whose entries are all rounding noise gets rank 0 (2^19 ε ≈ 1.2e-10).
inline constexpr double kPairRankRelative = 0x1p19 * kEpsilon;
/// Column-pivoted QR (linalg::pivoted_column_order): remaining column norms within this
/// fraction of the largest are a tie, taken in the columns' original order, so that rounding
/// (a model moved, turned or rescaled) cannot pick among equally good rows to release or
/// coordinates to constrain (2^26 ε ≈ 1.5e-8: far above rounding, far below a real difference).
inline constexpr double kPivotTie = 0x1p26 * kEpsilon;
/// Verdict participants (design::rank_participants): shares (0 to 1) within this of the largest
/// share of their group rank alike, in model order — half the unit of the four decimals the
/// reports print, so parts a designer sees as equal (legs of a symmetric robot given to a few
/// decimals) keep their model order, and rounding noise (a parallel run's, or another kernel's)
/// can neither reorder them nor change the change set chosen from them.
inline constexpr double kParticipationTie = 5e-5;
/// A variable can be chosen free in floating point when its row of the orthonormal null-space
/// basis keeps this much norm after removing earlier choices (2^22 ε ≈ 9.3e-10).
inline constexpr double kFreeVariableResidual = 0x1p22 * kEpsilon;
/// The SVD's self-check: ‖A − U Σ Vᵀ‖ and the orthonormality of U and V (on probe vectors)
/// pass below this, relative to max(1, ‖A‖) (2^19 ε ≈ 1.2e-10).
inline constexpr double kSvdResidualTolerance = 0x1p19 * kEpsilon;
/// Row and column equilibration stops when log2 of every row and column maximum is within this
/// of 0 (not a rounding level: equilibration only improves conditioning and changes no rank).
inline constexpr double kEquilibrationTolerance = 1e-3;

// --- Values shown as zero --------------------------------------------------------------------

/// Coefficients of a null-space basis below this fraction of the largest are stored and printed
/// as zero (2^12 ε ≈ 9.1e-13).
inline constexpr double kCoefficientZero = 0x1p12 * kEpsilon;
/// A mode or stress entry below this fraction of the largest in its vector is not listed
/// (2^22 ε ≈ 9.3e-10).
inline constexpr double kModeZero = 0x1p22 * kEpsilon;
/// A share of a mode or self-stress (a fraction of its squared norm) below this is not listed
/// (2^12 ε ≈ 9.1e-13).
inline constexpr double kShareZero = 0x1p12 * kEpsilon;
/// A number printed in a report below this in magnitude (values already non-dimensional or
/// normalised to a largest entry of 1) is printed as 0 (2^12 ε ≈ 9.1e-13).
inline constexpr double kPrintedZero = 0x1p12 * kEpsilon;
/// A twist or wrench whose linear part is below this fraction of its angular part is a pure
/// rotation (or force) through a point; one whose angular part is this small is a pure
/// translation (or couple) (2^22 ε ≈ 9.3e-10).
inline constexpr double kScrewZero = 0x1p22 * kEpsilon;
/// A body's share of a sparse null vector below this fraction of the largest is not listed as
/// taking part (2^22 ε ≈ 9.3e-10).
inline constexpr double kSupportZero = 0x1p22 * kEpsilon;
/// The sparse network verdict skips the exact idle-spin analysis of a body whose own unit actions
/// (its column block of K, floating point) have σ_min above this fraction of σ_max, and above
/// kIdleSpinScreenMargin × the rank tolerance: such a body cannot spin. Far above rounding, so
/// the screen never hides a spin; doubtful bodies get the exact analysis.
inline constexpr double kIdleSpinScreen = 1e-4;
inline constexpr double kIdleSpinScreenMargin = 100.0;
/// The design search keeps a change only when every unit motion of the bodies carrying the
/// intended motion (conditioned about the model's centroid, lengths over its size) lies within
/// this distance of the changed design's motions: far above the rounding of a null space
/// (~1e-13), far below a lost motion (of order 1).
inline constexpr double kMotionSpaceResidual = 1e-6;
/// Lengths and arrows in a drawing below this fraction of the drawing's extent are not drawn,
/// and two segments closer than this do not cross (2^22 ε ≈ 9.3e-10).
inline constexpr double kDrawnZero = 0x1p22 * kEpsilon;

// --- Geometry of input files -----------------------------------------------------------------

/// Two nodes closer than this fraction of the model's characteristic length coincide, and an
/// element this short has no direction (2^12 ε ≈ 9.1e-13).
inline constexpr double kCoincident = 0x1p12 * kEpsilon;
/// A given local axis and the element's axis are parallel when the sine of their angle is below
/// this (2^22 ε ≈ 9.3e-10).
inline constexpr double kParallelAxes = 0x1p22 * kEpsilon;
/// A user's triad (an element frame) must satisfy |R Rᵀ − I| below this, and a given axis must
/// align with its element to this, so that 7-digit decimals such as 0.7071068 pass (2^32 ε ≈ 9.5e-7).
inline constexpr double kOrientationTolerance = 0x1p32 * kEpsilon;
/// An imported robot's axis or offset keeps 12 significant digits of its largest entry, so the
/// noise of the exporter's pose arithmetic (1.8000000000000003, cos 90° = 6e-17) goes: entries
/// below this fraction of the largest are zero (a decimal precision, hence not 2^k ε).
inline constexpr double kImportNoise = 1e-12;

// --- Second order and finite motion (framework/ and network/ second_order.hpp, finite_motion.hpp) ---

/// A self-stress does no work on a mode at second order when |σᵀε″(u, u)| is below this
/// fraction of ‖ε″(u, u)‖ (unit σ): a finite mechanism leaves rounding only (2^26 ε ≈ 1.5e-8).
inline constexpr double kSecondOrderWorkZero = 0x1p26 * kEpsilon;
/// A combination of self-stresses makes the geometric stiffness positive definite on the
/// non-rigid modes when its smallest eigenvalue there exceeds this fraction of the largest
/// Frobenius norm of the stiffnesses of the orthonormal stress basis (2^26 ε ≈ 1.5e-8).
inline constexpr double kPrestressMargin = 0x1p26 * kEpsilon;
/// A unit mode whose component outside the rigid motions of the whole model is below this is a
/// rigid motion; the same cut keeps directions when orthonormalising bases (2^26 ε ≈ 1.5e-8).
inline constexpr double kRigidMotionZero = 0x1p26 * kEpsilon;
/// A traced path closes when every point satisfies the constraints to this fraction of the
/// characteristic length (the 1e-10 of issue 13; not a rounding level, a promise). Networks:
/// every circuit's closure error, rotation in rad × L plus translation, over L.
inline constexpr double kTraceResidual = 1e-10;
/// The corrector stops improving a point below this fraction of the characteristic length
/// (2^6 ε ≈ 1.4e-14): rounding of the bar lengths, or of a circuit's product of exponentials.
inline constexpr double kCorrectorTarget = 0x1p6 * kEpsilon;
/// A tangent whose projection on the null space of D(c) (networks: of the closure Jacobian)
/// keeps less than this fraction of its length has lost the mode (a corner the predictor cannot follow; a ratio, not rounding).
inline constexpr double kTangentKept = 1e-3;

// --- Position analysis (kinematics/position_solver.hpp) --------------------------------------

/// A closed-form discriminant of a group (a squared length over its scale, or 1 − cos²)
/// within this of zero is a singular position, where two assembly branches meet; below
/// −this the group cannot be assembled (2^8 ε ≈ 5.7e-14: rounding of squared lengths).
inline constexpr double kAssemblyDiscriminant = 0x1p8 * kEpsilon;
/// Newton's method places a group when its closure residual (lengths over the characteristic
/// length, angles in rad) is at most this (the 1e-10 of issue 13, as for traces).
inline constexpr double kPositionResidual = 1e-10;
/// A group placed by Newton whose Jacobian has σ_min below this fraction of σ_max is at a
/// singular position (2^26 ε ≈ 1.5e-8).
inline constexpr double kSingularPosition = 0x1p26 * kEpsilon;

// --- Stiffness (framework/stiffness.hpp, issue 38) ------------------------------------------

/// Rigid constraints of a stiffness model (rigid bodies, elements without elastic data): a
/// singular value of the length-scaled constraint matrix below this × its largest is dependent
/// (2^26 ε ≈ 1.5e-8), so its admissible motions are a null space from a rank-revealing SVD.
inline constexpr double kRigidConstraintRank = 0x1p26 * kEpsilon;
/// A stiffness eigenvalue (length-scaled, pivot of the LDLT of the condensed matrix) below this ×
/// the largest is a zero-stiffness motion: the node has a mechanism and no compliance
/// (2^16 ε ≈ 1.5e-11: rounding of the condensation; a thin flexure's motion stiffness is
/// 1e-4 to 1e-8 of its support stiffness, well above).
inline constexpr double kZeroStiffness = 0x1p16 * kEpsilon;
/// An off-diagonal entry of a condensed stiffness or compliance (length-scaled), or a component of
/// a principal direction (unit length, scaled), at most this × the largest is rounding and set to
/// 0, so that a coupling the geometry rules out reads 0 and not 1e-11 (2^12 ε ≈ 9.1e-13).
inline constexpr double kStiffnessRoundingZero = 0x1p12 * kEpsilon;
/// A held deformation takes part in a self-stress (and gets the misfit in turn) when its largest
/// component over the unit self-stress basis exceeds this × the largest of all; an element carries
/// the worst misfit case when its force (or moment) exceeds this × the largest force (moment)
/// (2^26 ε ≈ 1.5e-8: rounding of an SVD basis, far below any designed share).
inline constexpr double kMisfitParticipation = 0x1p26 * kEpsilon;
/// A direction of the mass matrix whose eigenvalue is below this × the largest has no mass and is
/// condensed out before the eigenfrequencies (2^26 ε ≈ 1.5e-8: rounding of Nᵀ M N when rigid
/// constraints reduce the coordinates; a lumped mass matrix's massless rows are exactly zero).
inline constexpr double kMasslessRelative = 0x1p26 * kEpsilon;

/// The tolerances of one analysis: what `--tolerance` sets, and the named defaults of every
/// other rank decision that follows it.
struct Tolerances {
  /// Relative rank threshold: singular values (or sparse R diagonal entries) above
  /// `rank × σ_max` of the scaled, non-dimensional matrix count in the rank. Unset: the
  /// LAPACK / NumPy / MATLAB rule max(rows, cols) · ε (sparse: kSparseToleranceFactor ·
  /// (rows + cols) · ε).
  std::optional<double> rank;
  /// Pair freedoms of a network: relative to the size of the whole network's forms.
  double pair_rank = kPairRankRelative;
  /// Free-variable choice in floating point (see kFreeVariableResidual).
  double free_variable = kFreeVariableResidual;

  /// The defaults with a user's relative tolerance (when given) applied to every rank decision:
  /// the main rank, pair freedoms and the free-variable choice.
  static Tolerances with_rank(std::optional<double> relative) {
    Tolerances t;
    if (relative) t.rank = t.pair_rank = t.free_variable = *relative;
    return t;
  }
};

}  // namespace kinestat
