// SPDX-License-Identifier: BSD-3-Clause
// The cost of over-constraint in the pictures (issue 38, item 5): the stress the worst misfit
// locks in, drawn on the elements as a stress entry, and the lowest eigenmodes animated as
// modes. The same entry kinds as self-stresses and kinematic modes, so every writer draws them
// without a drawing path of their own; the values are the analysis' (pipeline::framework_cost),
// only arranged here.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "kinestat/report/scene.hpp"
#include "kinestat/report/stiffness_report.hpp"

namespace kinestat::report {

namespace {

// Coordinates whose share of a mode shape is below this fraction of the largest are not listed
// as moving (a display choice: which coordinates the side panel names, not a numerical test).
constexpr double kListedModeShare = 0.01;

std::string cost_number(double value) { return fmt::format("{:.4g}", value); }

std::string cost_deformation_label(const framework::FrameworkModel& model, const framework::FrameworkIndexing& indexing,
                              Eigen::Index d) {
  const framework::DeformationRef& ref = indexing.deformations[static_cast<std::size_t>(d)];
  const framework::Element& element = model.elements[ref.element];
  return element.name + "." + framework::deformation_names(model, element)[ref.deformation];
}

// The stress entry of the worst misfit: per scene line of a truss or beam, the peak stress of
// its element (every carrying element has a section) or else its axial force; the kind of
// resultant that dominates, for the colour.
SceneStress misfit_stress(const Scene& scene, const framework::FrameworkModel& model, const framework::AnalysedCost& analysed) {
  const framework::OverConstraintCost& cost = *analysed.cost;
  const framework::MisfitResult& m = cost.misfit;
  const CostUnits u = cost_units(model);
  const bool stresses = std::all_of(m.elements.begin(), m.elements.end(),
                                    [](const framework::ElementStressResultants& e) { return std::isfinite(e.stress); });
  // Without a stress (sections given by rigidities): the bending moment when some element
  // carries one, else the axial force.
  const bool moments = !stresses && std::any_of(m.elements.begin(), m.elements.end(),
                                                [](const framework::ElementStressResultants& e) { return e.moment != 0.0; });
  const auto shown = [&](const framework::ElementStressResultants& e) {
    return stresses ? e.stress : moments ? e.moment : std::abs(e.force);
  };
  SceneStress entry;
  entry.unit = stresses ? u.stress : moments ? u.moment : "N";
  const std::string amount = analysed.per_unit ? fmt::format("per {} of misfit", u.length)
                                               : fmt::format("from a misfit of {} {}", cost_number(m.worst_misfit), u.length);
  const framework::ElementStressResultants& w = m.worst;
  entry.label = fmt::format("misfit stress {} in {}: worst {}, {} {} {}", amount,
                            cost_deformation_label(model, cost.indexing, *m.worst_source), model.elements[w.element].name,
                            stresses ? "peak stress" : moments ? "bending moment" : "axial force",
                            cost_number(stresses || moments ? shown(w) : w.force), entry.unit);
  entry.value.assign(scene.elements.size(), 0.0);
  entry.kind.assign(scene.elements.size(), "");
  std::map<std::string, const framework::ElementStressResultants*> carried;
  for (const auto& e : m.elements) carried[model.elements[e.element].name] = &e;
  for (std::size_t line = 0; line < scene.elements.size(); ++line) {
    const SceneElement& drawn = scene.elements[line];
    const auto found = carried.find(drawn.name);
    if (drawn.type == "rigid" || drawn.type == "link" || found == carried.end()) continue;
    const framework::ElementStressResultants& e = *found->second;
    const bool axial = e.moment == 0.0 && e.torque == 0.0;
    entry.kind[line] = axial ? "elongation" : e.moment != 0.0 ? "bending" : "torsion";
    const double size = shown(e);
    entry.value[line] = axial && e.force < 0.0 ? -size : size;
  }
  for (const auto& e : m.elements) {
    const std::string& name = model.elements[e.element].name;
    entry.resultants.push_back({name, "force N", e.force});
    if (e.moment != 0.0) entry.resultants.push_back({name, "moment " + u.moment, e.moment});
    if (e.torque != 0.0) entry.resultants.push_back({name, "torque " + u.moment, e.torque});
    if (stresses) entry.resultants.push_back({name, "peak stress " + u.stress, e.stress});
  }
  return entry;
}

// Eigenmode k of `modes` (shapes over cost.free) as a scene mode: every node's translation,
// scaled so that the largest is 1 (the viewer scales it to the picture anyway).
SceneMode eigenmode(const framework::FrameworkModel& model, const framework::AnalysedCost& analysed,
                    const framework::VibrationModes& modes, Eigen::Index k) {
  const framework::OverConstraintCost& cost = *analysed.cost;
  SceneMode mode;
  mode.kind = "vibration";
  mode.label = fmt::format("eigenmode {}: {} Hz", k + 1, cost_number(modes.frequencies(k)));
  if (!analysed.per_unit && cost.modes_with && k < cost.modes_with->frequencies.size())
    mode.label += fmt::format(" ({} Hz with the misfit)", cost_number(cost.modes_with->frequencies(k)));
  mode.first_order_reason = "an eigenmode of small free vibration about the configuration (linear)";
  mode.velocity.assign(model.nodes.size(), Eigen::Vector3d::Zero());
  const double length = framework::characteristic_length(model);
  Eigen::VectorXd share(static_cast<Eigen::Index>(cost.free.size()));  // rotations × length: one unit
  for (std::size_t i = 0; i < cost.free.size(); ++i) {
    const framework::CoordinateRef& ref = cost.indexing.coordinates[static_cast<std::size_t>(cost.free[i])];
    const double value = modes.shapes(static_cast<Eigen::Index>(i), k);
    if (framework::is_translation(ref.slot)) mode.velocity[ref.node](ref.slot) = value;
    share(static_cast<Eigen::Index>(i)) = std::abs(value) * (framework::is_translation(ref.slot) ? 1.0 : length);
  }
  double largest = 0.0;
  for (const Eigen::Vector3d& v : mode.velocity) largest = std::max(largest, v.norm());
  if (largest > 0.0)
    for (Eigen::Vector3d& v : mode.velocity) v /= largest;
  const double top = share.size() ? share.maxCoeff() : 0.0;
  for (std::size_t i = 0; i < cost.free.size(); ++i)
    if (top > 0.0 && share(static_cast<Eigen::Index>(i)) >= kListedModeShare * top) {
      const framework::CoordinateRef& ref = cost.indexing.coordinates[static_cast<std::size_t>(cost.free[i])];
      mode.moving.push_back(model.nodes[ref.node].name + "." + framework::kSlotNames[static_cast<std::size_t>(ref.slot)]);
    }
  return mode;
}

}  // namespace

void add_framework_cost(Scene& scene, const framework::FrameworkModel& model, const framework::AnalysedCost& analysed) {
  if (!analysed.cost) {
    scene.summary.push_back({"cost of over-constraint", analysed.not_computed});
    return;
  }
  const framework::OverConstraintCost& cost = *analysed.cost;
  const framework::MisfitResult& m = cost.misfit;
  const CostUnits u = cost_units(model);
  if (m.self_stresses == 0) {
    scene.summary.push_back({"misfit stress", "none: exactly constrained against misfit"});
  } else if (m.computed && m.worst_source) {
    scene.stresses.push_back(misfit_stress(scene, model, analysed));
    const double worst = std::isfinite(m.worst.stress) ? m.worst.stress : m.worst.force;
    scene.summary.push_back({analysed.per_unit ? fmt::format("worst misfit stress per {}", u.length)
                                               : fmt::format("worst stress at {} {} misfit", cost_number(m.worst_misfit), u.length),
                             fmt::format("{} {} in {}", cost_number(worst), std::isfinite(m.worst.stress) ? u.stress : "N",
                                         model.elements[m.worst.element].name)});
  }
  if (!cost.modes_without) return;
  const framework::VibrationModes& modes = *cost.modes_without;
  const Eigen::Index count = std::min(kReportedFrequencies, modes.frequencies.size());
  for (Eigen::Index k = 0; k < count; ++k) scene.modes.push_back(eigenmode(model, analysed, modes, k));
  if (count > 0) scene.summary.push_back({"lowest eigenfrequency", fmt::format("{} Hz", cost_number(modes.frequencies(0)))});
}

}  // namespace kinestat::report
