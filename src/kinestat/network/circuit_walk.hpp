// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The circuits of a coupling network as products of exponentials (issue 13): each circuit of the
// analysis (a row of B) walked from its chord's `from` body, coupling by coupling, each coupling
// expanded into its magnitudes in the order of its own serial chain (the `from` side first),
// reversed when the walk passes the coupling from `to` to `from`. Around the circuit
//     Π_k exp(sign_k · S_k · θ_k) = I     (left to right in walking order)
// is the loop-closure equation of the product-of-exponentials formula, S_k the unit twist of
// magnitude k at the model's configuration (both the second-order test and the finite-motion
// trace use it).

#include <vector>

#include "kinestat/network/model.hpp"
#include "kinestat/network/network_result.hpp"
#include "kinestat/screw/coupling_type.hpp"

namespace kinestat::network {

/// One factor of a circuit's product of exponentials: a magnitude (index into
/// NetworkResult::motions) and the sign it enters with (+1 when the walk passes its coupling
/// from `from` to `to`, −1 otherwise).
struct CircuitFactor {
  int magnitude = 0;
  double sign = 1.0;
};

/// True when the finite motion of a coupling of this type is the product of the exponentials of
/// its unit twists in the order coupling_basis lists them (lower pairs; universal: `axis` on
/// the `from` side first). False for point_on_plane, point_on_line (their finite motion needs
/// curvatures the model does not give) and custom screws.
bool has_product_of_exponentials_model(screw::CouplingType type);

/// The factors of every circuit of `result` (the analysis of `model`), one list per row of B in
/// row order. A list is empty when the couplings of its row do not form a closed walk.
std::vector<std::vector<CircuitFactor>> circuit_walks(const Model& model, const NetworkResult& result);

}  // namespace kinestat::network
