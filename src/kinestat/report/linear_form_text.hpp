// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Linear forms in primary variables as text: "Ub - We", "-sa", "0.5*vc", "0".

#include <Eigen/Core>

#include <string>
#include <vector>

#include "kinestat/network/network_result.hpp"

namespace kinestat::report {

/// Row `row` of `forms` as an expression in `names`. Exact forms print exact rationals;
/// floating-point coefficients print with 10 significant digits, and coefficients below
/// `zero_below` in magnitude print as nothing (rounding noise).
std::string linear_form_text(const network::LinearForms& forms, Eigen::Index row, const std::vector<std::string>& names,
                             double zero_below = 0.0);

/// A number with up to 10 significant digits and no trailing noise ("0.5", "1e-12").
std::string number_text(double value);

}  // namespace kinestat::report
