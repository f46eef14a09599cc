// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/design/network_change_application.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>
#include <string>

#include "kinestat/error.hpp"
#include "kinestat/screw/coupling_type.hpp"

namespace kinestat::design {

namespace {

// The shortest decimal that reads back as `x` (fmt's "{}" of a double), as an exact rational:
// "0.1" is 1/10, not the binary fraction nearest to it.
screw::Rational shortest_decimal_of(double x) {
  const std::string text = fmt::format("{}", x);
  const std::size_t e = text.find_first_of("eE");
  const std::string mantissa = text.substr(0, e);
  long exponent = e == std::string::npos ? 0 : std::strtol(text.c_str() + e + 1, nullptr, 10);
  std::string digits;
  for (const char c : mantissa) {
    if (c == '.') continue;
    digits += c;
  }
  const std::size_t dot = mantissa.find('.');
  if (dot != std::string::npos) exponent -= static_cast<long>(mantissa.size() - dot - 1);
  screw::Rational value{mpz_class(digits, 10)};
  mpz_class scale = 1;
  mpz_ui_pow_ui(scale.get_mpz_t(), 10, static_cast<unsigned long>(std::labs(exponent)));
  if (exponent >= 0) value *= scale;
  else value /= scale;
  value.canonicalize();
  return value;
}

// `x` as an exact number: one of `known` (the coupling's own exact numbers) that has this value
// as a double, else an integer, else the shortest decimal.
screw::Rational exact_change_number(double x, const std::vector<screw::Rational>& known) {
  if (!std::isfinite(x)) throw Error(fmt::format("a change's geometry holds {}, not a finite number", x));
  for (const screw::Rational& k : known)
    if (k.get_d() == x) return k;
  if (x == std::trunc(x) && std::abs(x) < 0x1p53) return screw::Rational(mpz_class(static_cast<long>(std::llround(x))));
  return shortest_decimal_of(x);
}

screw::Vec3 exact_change_vector(const std::vector<double>& v, const std::vector<screw::Rational>& known, const std::string& key, const std::string& target) {
  if (v.size() != 3)
    throw Error(fmt::format("the change of coupling '{}' gives '{}' with {} numbers, not 3", target, key, v.size()));
  return {exact_change_number(v[0], known), exact_change_number(v[1], known), exact_change_number(v[2], known)};
}

// Every exact number of a coupling's geometry.
std::vector<screw::Rational> coupling_numbers(const screw::CouplingGeometry& g) {
  std::vector<screw::Rational> out(g.point.begin(), g.point.end());
  for (const auto* v : {&g.axis, &g.axis2, &g.normal})
    if (*v) out.insert(out.end(), (*v)->begin(), (*v)->end());
  return out;
}

network::Coupling replaced_coupling(const network::Coupling& before, const DesignChange& change) {
  const auto type = screw::parse_coupling_type(change.becomes);
  if (!type || *type == screw::CouplingType::custom)
    throw Error(fmt::format("the change of coupling '{}' makes it '{}', which is no coupling type a change can give", change.target,
                            change.becomes));
  network::Coupling after = before;
  after.type = *type;
  after.geometry = screw::CouplingGeometry{};
  after.geometry.point = before.geometry.point;
  const std::vector<screw::Rational> known = coupling_numbers(before.geometry);
  const std::vector<std::string_view> used = screw::geometry_keys(*type);
  for (const auto& [key, value] : change.geometry) {
    const screw::Vec3 v = exact_change_vector(value, known, key, change.target);
    if (key == "point") {
      after.geometry.point = v;
      continue;
    }
    if (std::find(used.begin(), used.end(), key) == used.end())
      throw Error(fmt::format("the change of coupling '{}' gives '{}', which a {} coupling does not use", change.target, key,
                              change.becomes));
    if (key == "axis") after.geometry.axis = v;
    else if (key == "axis2") after.geometry.axis2 = v;
    else if (key == "normal") after.geometry.normal = v;
    else throw Error(fmt::format("the change of coupling '{}' gives '{}', which is no coupling geometry", change.target, key));
  }
  for (const std::string_view key : screw::required_geometry_keys(*type)) {
    const bool given = (key == "point") || (key == "axis" && after.geometry.axis) || (key == "axis2" && after.geometry.axis2) ||
                       (key == "normal" && after.geometry.normal);
    if (!given)
      throw Error(fmt::format("the change of coupling '{}' to {} gives no '{}'", change.target, change.becomes, key));
  }
  return after;
}

}  // namespace

network::Model apply_network_change_set(const network::Model& model, const std::vector<DesignChange>& changes) {
  // Each change by the index of the coupling it names; a coupling changes at most once.
  std::map<std::size_t, const DesignChange*> by_coupling;
  for (const DesignChange& change : changes) {
    if (change.target_kind != "coupling")
      throw Error(fmt::format("a network's change names a {} ('{}'), not a coupling", change.target_kind, change.target));
    const auto it = std::find_if(model.couplings.begin(), model.couplings.end(),
                                 [&](const network::Coupling& c) { return c.name == change.target; });
    if (it == model.couplings.end()) throw Error(fmt::format("the change names coupling '{}', which the model does not have", change.target));
    const auto index = static_cast<std::size_t>(it - model.couplings.begin());
    if (!by_coupling.emplace(index, &change).second)
      throw Error(fmt::format("the change set changes coupling '{}' twice", change.target));
  }
  network::Model m = model;
  m.chords.clear();
  m.primary.clear();
  m.values.clear();
  m.couplings.clear();
  m.couplings.reserve(model.couplings.size());
  for (std::size_t i = 0; i < model.couplings.size(); ++i) {
    const auto it = by_coupling.find(i);
    if (it == by_coupling.end()) {
      m.couplings.push_back(model.couplings[i]);
      continue;
    }
    const DesignChange& change = *it->second;
    if (change.action == "remove" || change.becomes == "removed") {
      const std::string& name = model.couplings[i].name;
      m.inputs.erase(std::remove(m.inputs.begin(), m.inputs.end(), name), m.inputs.end());
      continue;
    }
    if (change.action != "release" && change.action != "constrain" && change.action != "replace")
      throw Error(fmt::format("a network's change '{}' of coupling '{}' is none of remove, release, constrain, replace", change.action,
                              change.target));
    m.couplings.push_back(replaced_coupling(model.couplings[i], change));
  }
  return m;
}

}  // namespace kinestat::design
