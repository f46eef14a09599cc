// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/report/linear_form_text.hpp"
#include "kinestat/tolerances.hpp"

#include <fmt/format.h>

#include <cmath>

namespace kinestat::report {

std::string number_text(double value) {
  if (value == 0.0) return "0";  // also turns -0 into 0
  return fmt::format("{:.10g}", value);
}

std::string linear_form_text(const network::LinearForms& forms, Eigen::Index row, const std::vector<std::string>& names,
                             double zero_below) {
  std::string text;
  for (Eigen::Index p = 0; p < forms.values.cols(); ++p) {
    std::string magnitude;  // the coefficient's absolute value, "" for one
    bool negative = false;
    if (forms.exact) {
      const linalg::Rational& c = (*forms.exact)(row, p);
      if (sgn(c) == 0) continue;
      negative = sgn(c) < 0;
      const linalg::Rational absolute = abs(c);
      if (absolute != 1) magnitude = absolute.get_str();
    } else {
      const double c = forms.values(row, p);
      if (std::abs(c) <= zero_below || c == 0.0) continue;
      negative = c < 0;
      if (std::abs(std::abs(c) - 1.0) > kPrintedZero) magnitude = number_text(std::abs(c));
    }
    const std::string term = (magnitude.empty() ? "" : magnitude + "*") + names[static_cast<std::size_t>(p)];
    if (text.empty()) {
      text = (negative ? "-" : "") + term;
    } else {
      text += (negative ? " - " : " + ") + term;
    }
  }
  return text.empty() ? "0" : text;
}

}  // namespace kinestat::report
