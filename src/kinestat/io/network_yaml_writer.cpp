// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/network_yaml_writer.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace kinestat::io {

namespace {

std::string yaml_quoted(const std::string& text) { return nlohmann::json(text).dump(); }

// A rational as a decimal: exact when its denominator has no prime factors but 2 and 5.
std::string decimal(const screw::Rational& value) {
  mpz_class denominator = value.get_den();
  int twos = 0, fives = 0;
  while (mpz_divisible_ui_p(denominator.get_mpz_t(), 2)) denominator /= 2, ++twos;
  while (mpz_divisible_ui_p(denominator.get_mpz_t(), 5)) denominator /= 5, ++fives;
  if (denominator != 1 || std::max(twos, fives) > 40) return fmt::format("{:.17g}", value.get_d());
  const int digits = std::max(twos, fives);
  mpz_class scaled = value.get_num();
  for (int i = 0; i < digits - twos; ++i) scaled *= 2;
  for (int i = 0; i < digits - fives; ++i) scaled *= 5;
  const bool negative = scaled < 0;
  std::string text = mpz_class(abs(scaled)).get_str();
  if (digits > 0) {
    if (static_cast<int>(text.size()) <= digits) text = std::string(static_cast<std::size_t>(digits) - text.size() + 1, '0') + text;
    text.insert(text.size() - static_cast<std::size_t>(digits), ".");
  }
  return (negative ? "-" : "") + text;
}

std::string yaml_vector(const screw::Vec3& v) { return fmt::format("[{}, {}, {}]", decimal(v[0]), decimal(v[1]), decimal(v[2])); }

// A custom coupling's screws: [[d numbers], ...].
std::string yaml_screws(const std::vector<std::vector<screw::Rational>>& screws) {
  std::string out = "[";
  for (std::size_t k = 0; k < screws.size(); ++k) {
    out += k ? ", [" : "[";
    for (std::size_t i = 0; i < screws[k].size(); ++i) out += (i ? ", " : "") + decimal(screws[k][i]);
    out += "]";
  }
  return out + "]";
}

}  // namespace

std::string network_yaml(const network::Model& model, const std::vector<std::string>& comments) {
  std::string out;
  for (const auto& c : comments) out += "# " + c + "\n";
  out += "kinestat: 1\nkind: network\n";
  if (!model.name.empty()) out += "name: " + yaml_quoted(model.name) + "\n";
  out += model.space.is_planar() ? "dimension: planar\n" : "dimension: spatial\n";
  if (!model.units.empty()) out += "units: " + yaml_quoted(model.units) + "\n";
  out += "bodies: [";
  for (std::size_t b = 0; b < model.bodies.size(); ++b) out += (b ? ", " : "") + yaml_quoted(model.bodies[b]);
  out += "]\n";
  if (model.ground) out += "ground: " + yaml_quoted(model.bodies[static_cast<std::size_t>(*model.ground)]) + "\n";
  out += "couplings:\n";
  for (const auto& c : model.couplings) {
    out += fmt::format("  - {{name: {}, type: {}, between: [{}, {}], point: {}", yaml_quoted(c.name), screw::coupling_type_name(c.type),
                       yaml_quoted(model.bodies[static_cast<std::size_t>(c.from)]), yaml_quoted(model.bodies[static_cast<std::size_t>(c.to)]),
                       yaml_vector(c.geometry.point));
    if (c.geometry.axis) out += ", axis: " + yaml_vector(*c.geometry.axis);
    if (c.geometry.axis2) out += ", axis2: " + yaml_vector(*c.geometry.axis2);
    if (c.geometry.normal) out += ", normal: " + yaml_vector(*c.geometry.normal);
    if (c.type == screw::CouplingType::helical) out += ", pitch: " + decimal(c.geometry.pitch);
    if (!c.geometry.custom_motions.empty()) out += ", motions: " + yaml_screws(c.geometry.custom_motions);
    if (!c.geometry.custom_actions.empty()) out += ", actions: " + yaml_screws(c.geometry.custom_actions);
    out += "}\n";
  }
  if (!model.inputs.empty()) {
    out += "inputs: [";
    for (std::size_t i = 0; i < model.inputs.size(); ++i) out += (i ? ", " : "") + yaml_quoted(model.inputs[i]);
    out += "]\n";
  }
  return out;
}

}  // namespace kinestat::io
