// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Generated pin-jointed lattices for benchmarks and cross-checks of the sparse path: their
// counts follow from the geometry (Maxwell's rule and the shear of layers), so they need no
// analysis to be known.

#include "kinestat/framework/framework_model.hpp"

namespace kinestat::framework {

/// An n × n planar grid of unit cells, nodes "n<k>" (k = row · n + column), bottom row pinned.
/// Without diagonals: n − 1 mechanisms (each row of vertical bars shears) and n − 1
/// self-stresses (the bars between pinned nodes). With one diagonal per cell (a triangular
/// lattice): rigid, 2n(n − 1) + (n − 1)² bars on 2n(n − 1) free coordinates, so (n − 1)²
/// self-stresses.
FrameworkModel planar_lattice(int n, bool diagonals);

/// An n × n × n cubic lattice, base layer pinned, one diagonal in every horizontal face:
/// 3(n − 1) mechanisms (each triangulated layer moves as a plate in its own plane over the
/// vertical bars below it: x, y and a twist about z).
FrameworkModel spatial_lattice(int n);

/// Side of a lattice with `per_cell` bars per cell in `dimension` dimensions whose bar count is
/// closest to `bars`.
int lattice_side(double bars, double per_cell, int dimension);

}  // namespace kinestat::framework
