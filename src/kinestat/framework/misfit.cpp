// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/framework/misfit.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "kinestat/framework/stiffness.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::framework {

namespace {

// The flexibility of the held rows of one element: the held block of K_e⁻¹ (its released
// deformations carry no resultant, so ε_held = (K_e⁻¹)_hh s_h); the inverse of the held block
// when K_e is singular (a released deformation without stiffness); zero for a rigid element.
Eigen::MatrixXd held_flexibility(const Eigen::MatrixXd& stiffness, const std::vector<Eigen::Index>& held) {
  const auto h = static_cast<Eigen::Index>(held.size());
  if (stiffness.size() == 0) return Eigen::MatrixXd::Zero(h, h);
  const Eigen::LDLT<Eigen::MatrixXd> whole(stiffness);
  Eigen::MatrixXd inverse = whole.solve(Eigen::MatrixXd::Identity(stiffness.rows(), stiffness.cols()));
  Eigen::MatrixXd block(h, h);
  if (whole.info() == Eigen::Success && inverse.allFinite() && whole.isPositive()) {
    for (Eigen::Index i = 0; i < h; ++i)
      for (Eigen::Index j = 0; j < h; ++j) block(i, j) = inverse(held[static_cast<std::size_t>(i)], held[static_cast<std::size_t>(j)]);
    return block;
  }
  for (Eigen::Index i = 0; i < h; ++i)
    for (Eigen::Index j = 0; j < h; ++j) block(i, j) = stiffness(held[static_cast<std::size_t>(i)], held[static_cast<std::size_t>(j)]);
  const Eigen::LDLT<Eigen::MatrixXd> part(block);
  return part.solve(Eigen::MatrixXd::Identity(h, h));
}

// The block-diagonal flexibility over the rows of D(c).
Eigen::MatrixXd row_flexibility(const FrameworkModel& model, const FrameworkResult& a, const std::vector<ElementCompliance>& compliance) {
  std::vector<Eigen::Index> row_of(a.indexing.deformations.size(), -1);
  for (Eigen::Index r = 0; r < a.m; ++r) row_of[static_cast<std::size_t>(a.rows[static_cast<std::size_t>(r)])] = r;
  Eigen::MatrixXd f = Eigen::MatrixXd::Zero(a.m, a.m);
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const Eigen::Index first = a.indexing.first_deformation[e];
    const auto count = static_cast<Eigen::Index>(deformation_count(model.dimension, model.elements[e]));
    std::vector<Eigen::Index> held, rows;
    for (Eigen::Index d = 0; d < count; ++d)
      if (const Eigen::Index r = row_of[static_cast<std::size_t>(first + d)]; r >= 0) {
        held.push_back(d);
        rows.push_back(r);
      }
    if (held.empty()) continue;
    const Eigen::MatrixXd& k = compliance[e].stiffness;
    if (k.size() != 0 && (k.rows() != count || k.cols() != count))
      throw std::invalid_argument("analyse_misfit: element " + model.elements[e].name + " has a stiffness of the wrong size");
    const Eigen::MatrixXd block = held_flexibility(k, held);
    for (std::size_t i = 0; i < rows.size(); ++i)
      for (std::size_t j = 0; j < rows.size(); ++j) f(rows[i], rows[j]) = block(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
  }
  return f;
}

// The peak normal stress at one end of a beam with axial force n and end moments about local y
// and z (NaN when the section cannot say).
double peak_stress(const ElementCompliance& c, double n, double moment_y, double moment_z) {
  if (c.area <= 0.0) return std::numeric_limits<double>::quiet_NaN();
  double stress = std::abs(n) / c.area;
  if (c.round) {
    const double moment = std::hypot(moment_y, moment_z);
    if (moment == 0.0) return stress;
    if (c.second_moment_y <= 0.0 || c.fibre_y <= 0.0) return std::numeric_limits<double>::quiet_NaN();
    return stress + moment * c.fibre_y / c.second_moment_y;
  }
  if (moment_y != 0.0) {
    if (c.second_moment_y <= 0.0 || c.fibre_z <= 0.0) return std::numeric_limits<double>::quiet_NaN();
    stress += std::abs(moment_y) * c.fibre_z / c.second_moment_y;
  }
  if (moment_z != 0.0) {
    if (c.second_moment_z <= 0.0 || c.fibre_y <= 0.0) return std::numeric_limits<double>::quiet_NaN();
    stress += std::abs(moment_z) * c.fibre_y / c.second_moment_z;
  }
  return stress;
}

// Whether `candidate` is worse than `current`: by peak stress when both have one, a known
// stress beats an unknown one, otherwise by |force|, then by |moment|.
bool misfit_worse(const ElementStressResultants& candidate, const ElementStressResultants& current) {
  const bool has_candidate = !std::isnan(candidate.stress), has_current = !std::isnan(current.stress);
  if (has_candidate && has_current) return candidate.stress > current.stress;
  if (has_candidate != has_current) return has_candidate;
  if (std::abs(candidate.force) != std::abs(current.force)) return std::abs(candidate.force) > std::abs(current.force);
  return candidate.moment > current.moment;
}

}  // namespace

double MisfitTolerance::of(const std::string& element) const {
  if (const auto named = per_element.find(element); named != per_element.end()) return named->second;
  return value.value_or(0.0);
}

std::optional<std::string> unknown_misfit_element(const FrameworkModel& model, const MisfitTolerance& tolerance) {
  // Not a structured binding: clang before 16 cannot capture one in a lambda.
  for (const auto& entry : tolerance.per_element) {
    const std::string& name = entry.first;
    const bool known = std::any_of(model.elements.begin(), model.elements.end(), [&](const Element& e) { return e.name == name; });
    if (!known) return name;
  }
  return std::nullopt;
}

std::vector<ElementCompliance> element_compliance(const FrameworkModel& model) {
  std::vector<ElementCompliance> out(model.elements.size());
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const Element& element = model.elements[e];
    ElementCompliance& c = out[e];
    if (std::optional<Eigen::MatrixXd> k = element_deformation_stiffness(model, element)) c.stiffness = std::move(*k);
    const Section* section = element_section(model, element);
    if (section == nullptr || element.type == ElementType::rigid_body) continue;
    if (section->shape == SectionShape::rigidities) continue;  // E A, E I only: no stress (A and E unknown apart)
    c.area = section->area;
    c.second_moment_y = section->iy;
    c.second_moment_z = section->iz;
    switch (section->shape) {
      case SectionShape::circle:
        c.round = true;
        c.fibre_y = c.fibre_z = section->dimensions[0] / 2;
        break;
      case SectionShape::rectangle:
        c.fibre_y = section->dimensions[0] / 2;
        c.fibre_z = section->dimensions[1] / 2;
        break;
      case SectionShape::area_only:
      case SectionShape::explicit_values:
      case SectionShape::rigidities: break;
    }
  }
  return out;
}

Eigen::VectorXd force_method_resultants(const Eigen::MatrixXd& self_stresses, const Eigen::MatrixXd& flexibility,
                                        const Eigen::VectorXd& misfit) {
  const Eigen::Index m = self_stresses.rows();
  if (flexibility.rows() != m || flexibility.cols() != m || misfit.size() != m)
    throw std::invalid_argument("force_method_resultants: S, F and e0 must have one row per held deformation");
  if (self_stresses.cols() == 0) return Eigen::VectorXd::Zero(m);
  const Eigen::MatrixXd compliance = self_stresses.transpose() * flexibility * self_stresses;
  const Eigen::LDLT<Eigen::MatrixXd> factor(compliance);
  const Eigen::VectorXd alpha = factor.solve(self_stresses.transpose() * misfit);
  // A self-stress through rigid members only has Sᵀ F S = 0 on it: a zero pivot, and LDLT's
  // solve gives infinity or NaN there (or a non-positive pivot from rounding).
  if (factor.info() != Eigen::Success || !factor.isPositive() || (factor.vectorD().array() <= 0.0).any() || !alpha.allFinite())
    throw std::invalid_argument("a self-stress runs through rigid members only: no finite stress takes up the misfit");
  return self_stresses * alpha;
}

Eigen::MatrixXd physical_self_stresses(const FrameworkModel& model, const FrameworkResult& a) {
  Eigen::MatrixXd s(a.m, static_cast<Eigen::Index>(a.stresses.size()));
  for (Eigen::Index k = 0; k < s.cols(); ++k) {
    const Eigen::VectorXd& scaled = a.stresses[static_cast<std::size_t>(k)].resultants;
    for (Eigen::Index r = 0; r < a.m; ++r) {
      const DeformationRef& d = a.indexing.deformations[static_cast<std::size_t>(a.rows[static_cast<std::size_t>(r)])];
      // D̂ divides a length-type row by the characteristic length, so σ̂ᵀ D̂ = 0 is σᵀ D = 0
      // with σ = σ̂ / length on those rows.
      const bool length_row = deformation_is_length(model.dimension, model.elements[d.element], d.deformation);
      s(r, k) = length_row ? scaled(r) / a.length : scaled(r);
    }
    if (const double norm = s.col(k).norm(); norm > 0.0) s.col(k) /= norm;
  }
  return s;
}

std::vector<ElementStressResultants> element_stress_resultants(const FrameworkModel& model, const FrameworkIndexing& indexing,
                                                               const Eigen::VectorXd& resultants,
                                                               const std::vector<ElementCompliance>& compliance) {
  std::vector<ElementStressResultants> out;
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const Element& element = model.elements[e];
    if (element.type == ElementType::rigid_body) continue;  // rigid: no section, no stress
    const Eigen::Index first = indexing.first_deformation[e];
    const ElementCompliance& c = compliance[e];
    ElementStressResultants r;
    r.element = e;
    r.force = resultants(first);
    if (element.type == ElementType::truss) {
      r.stress = c.area > 0.0 ? std::abs(r.force) / c.area : std::numeric_limits<double>::quiet_NaN();
    } else {
      // The beam's bending deformations are l0 × end angles, so their resultants are the end
      // moments over l0 (and the torsion resultant the torque over l0).
      const double l0 = (model.nodes[element.nodes[1]].position - model.nodes[element.nodes[0]].position).norm();
      double moment_y_p = 0.0, moment_y_q = 0.0, moment_z_p = 0.0, moment_z_q = 0.0;
      if (model.dimension == 2) {  // elongation, bending_p, bending_q: in-plane, about local z
        moment_z_p = l0 * resultants(first + 1);
        moment_z_q = l0 * resultants(first + 2);
      } else {  // elongation, torsion, bending_xz_p, bending_xz_q (about y), bending_xy_p, bending_xy_q (about z)
        r.torque = std::abs(l0 * resultants(first + 1));
        moment_y_p = l0 * resultants(first + 2);
        moment_y_q = l0 * resultants(first + 3);
        moment_z_p = l0 * resultants(first + 4);
        moment_z_q = l0 * resultants(first + 5);
      }
      r.moment = std::max(std::hypot(moment_y_p, moment_z_p), std::hypot(moment_y_q, moment_z_q));
      const double at_p = peak_stress(c, r.force, moment_y_p, moment_z_p), at_q = peak_stress(c, r.force, moment_y_q, moment_z_q);
      r.stress = std::isnan(at_p) || std::isnan(at_q) ? std::numeric_limits<double>::quiet_NaN() : std::max(at_p, at_q);
    }
    out.push_back(r);
  }
  return out;
}

MisfitResult analyse_misfit(const FrameworkModel& model, const FrameworkResult& a, const std::vector<ElementCompliance>& compliance,
                            const MisfitTolerance& tolerance) {
  if (compliance.size() != model.elements.size())
    throw std::invalid_argument("analyse_misfit: one compliance per element expected");
  if (const std::optional<std::string> unknown = unknown_misfit_element(model, tolerance))
    throw std::invalid_argument("--misfit: the model has no element named '" + *unknown + "'");
  MisfitResult result;
  result.value = tolerance.value.value_or(0.0);
  result.tolerance = tolerance;
  result.self_stresses = a.self_stresses;
  result.worst_resultants = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(a.indexing.deformations.size()));
  if (a.self_stresses == 0) {
    result.computed = true;
    return result;
  }
  if (!a.vectors || static_cast<Eigen::Index>(a.stresses.size()) != a.self_stresses) return result;
  result.computed = true;

  const Eigen::MatrixXd s = physical_self_stresses(model, a);
  const Eigen::MatrixXd f = row_flexibility(model, a, compliance);
  // s = S (Sᵀ F S)⁻¹ Sᵀ e₀ for e₀ = value × a unit row: one column of the influence matrix
  // G = S (Sᵀ F S)⁻¹ Sᵀ per misfit row, computed once.
  const Eigen::MatrixXd influence_of_unit = [&] {
    Eigen::MatrixXd g(a.m, a.m);
    for (Eigen::Index r = 0; r < a.m; ++r) g.col(r) = force_method_resultants(s, f, Eigen::VectorXd::Unit(a.m, r));
    return g;
  }();
  const double largest = s.cwiseAbs().maxCoeff();
  std::vector<ElementStressResultants> worst_elements;
  for (Eigen::Index r = 0; r < a.m; ++r) {
    const Eigen::Index deformation = a.rows[static_cast<std::size_t>(r)];
    const DeformationRef& d = a.indexing.deformations[static_cast<std::size_t>(deformation)];
    if (!deformation_is_length(model.dimension, model.elements[d.element], d.deformation)) continue;
    if (s.row(r).cwiseAbs().maxCoeff() <= kMisfitParticipation * largest) continue;
    result.participating.push_back(deformation);
    const double value = tolerance.of(model.elements[d.element].name);
    Eigen::VectorXd all = Eigen::VectorXd::Zero(result.worst_resultants.size());
    for (Eigen::Index i = 0; i < a.m; ++i) all(a.rows[static_cast<std::size_t>(i)]) = value * influence_of_unit(i, r);
    std::vector<ElementStressResultants> elements = element_stress_resultants(model, a.indexing, all, compliance);
    const auto top = std::max_element(elements.begin(), elements.end(),
                                      [](const ElementStressResultants& x, const ElementStressResultants& y) { return misfit_worse(y, x); });
    if (top == elements.end()) continue;
    if (!result.worst_source || misfit_worse(*top, result.worst)) {
      result.worst_source = deformation;
      result.worst_misfit = value;
      result.worst = *top;
      result.worst_resultants = all;
      worst_elements = std::move(elements);
      // The self-stress that carries most of this case: the largest coefficient on the unit basis.
      const Eigen::VectorXd shares = s.transpose() * influence_of_unit.col(r);
      shares.cwiseAbs().maxCoeff(&result.worst_self_stress);
    }
  }
  // Every element that carries part of the worst case, in model order.
  // Forces and moments are compared each with their own kind, so that no unit enters.
  double largest_force = 0.0, largest_moment = 0.0;
  for (const ElementStressResultants& e : worst_elements) {
    largest_force = std::max(largest_force, std::abs(e.force));
    largest_moment = std::max(largest_moment, e.moment);
  }
  for (const ElementStressResultants& e : worst_elements)
    if (std::abs(e.force) > kMisfitParticipation * largest_force || e.moment > kMisfitParticipation * largest_moment)
      result.elements.push_back(e);
  return result;
}

}  // namespace kinestat::framework
