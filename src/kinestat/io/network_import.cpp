// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/network_import.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <system_error>

#include "kinestat/io/printable_text.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::io {

namespace {

// A name must print in every report and read back from the YAML the network is written as: it
// is refused when io::printable_text would change it (XML lets `&#1;` and raw control bytes
// through; fuzzer).
void require_printable(const char* what, const std::string& name, const SourceLocation& where) {
  if (printable_text(name) != name)
    throw InputError(where, fmt::format("the {} name '{}' contains a control character, a bidirectional control or bytes "
                                        "that are not UTF-8; names must be printable text",
                                        what, name));
}
}  // namespace

std::string allowed_include(const std::string& target, const std::string& folder, const ImportOptions& options,
                            const SourceLocation& where, const std::string& written) {
  std::error_code error;
  const std::filesystem::path canonical = std::filesystem::canonical(target, error);
  if (error) throw InputError(where, fmt::format("cannot read the included file '{}': {}", printable_text(written), error.message()));
  const std::string text = canonical.string();
  // Compared after links are resolved, so that a link inside the folder cannot lead out of it.
  const bool inside = text.size() > folder.size() && text.compare(0, folder.size(), folder) == 0 &&
                      (folder.back() == '/' || text[folder.size()] == '/');
  if (!inside && !options.allow_includes_outside_folder)
    throw InputError(where, fmt::format("the include '{}' is {}, outside the model's folder {}: kinestat reads included files "
                                        "outside that folder only when the user allows it (kinestat's "
                                        "--allow-outside-includes)",
                                        printable_text(written), printable_text(text), printable_text(folder)));
  return text;
}

NetworkBuilder::NetworkBuilder(std::string path, std::string name, std::string units) : path_(std::move(path)) {
  require_printable("model", name, {path_, 0, 0});
  loaded_.model.name = std::move(name);
  loaded_.model.units = std::move(units);
  loaded_.model.space = screw::ScrewSpace::spatial();
}

int NetworkBuilder::body(const std::string& name) {
  const auto found = bodies_.find(name);
  if (found != bodies_.end()) return found->second;
  // A body needs a name that kinestat YAML can write and read back.
  if (name.empty()) throw InputError({path_, 0, 0}, "a link (or the ground) has an empty name; every link needs a name");
  require_printable("link", name, {path_, 0, 0});
  const int index = static_cast<int>(loaded_.model.bodies.size());
  bodies_[name] = index;
  loaded_.model.bodies.push_back(name);
  return index;
}

void NetworkBuilder::set_ground(const std::string& name) { loaded_.model.ground = body(name); }

screw::Vec3 NetworkBuilder::exact(const Eigen::Vector3d& v) {
  const double largest = v.cwiseAbs().maxCoeff();
  screw::Vec3 out;
  // Digits after the decimal point that keep 12 significant digits of the largest component.
  const int decimals = largest > 0 ? std::clamp(12 - static_cast<int>(std::floor(std::log10(largest))), 0, 340) : 0;
  for (int i = 0; i < 3; ++i) {
    const double c = std::abs(v(i)) < kImportNoise * largest ? 0.0 : v(i);
    std::string text = fmt::format("{:.{}f}", c, decimals);
    if (text.find('.') != std::string::npos) {
      while (text.back() == '0') text.pop_back();
      if (text.back() == '.') text.pop_back();
    }
    if (text == "-0") text.erase(0, 1);  // "0" (erase, not assignment: GCC 12 warns wrongly of overlapping copies)
    // A component that still has 12 significant digits was a genuinely long number (0.8660254…),
    // not a short decimal with rounding noise: such models are analysed in floating point.
    const int digits = significant_digits(text);
    digits_ = std::max(digits_, digits >= 12 ? 17 : digits);
    const auto decimal = parse_exact_decimal(text);
    out[static_cast<std::size_t>(i)] = decimal ? *decimal : screw::Rational(c);
  }
  return out;
}

void NetworkBuilder::couple(const std::string& name, screw::CouplingType type, const std::string& from, const std::string& to,
                            const JointGeometry& geometry, const SourceLocation& where) {
  require_printable("joint", name, where);
  for (const std::string& link : {from, to})
    if (!bodies_.count(link)) require_printable("link", link, where);
  if (coupling_names_.count(name)) throw InputError(where, fmt::format("duplicate joint name '{}'", name));
  if (from == to) throw InputError(where, fmt::format("joint '{}' joins link '{}' to itself", name, from));
  network::Coupling coupling;
  coupling.name = name;
  coupling.type = type;
  coupling.from = body(from);
  coupling.to = body(to);
  if (!geometry.point.allFinite()) throw InputError(where, fmt::format("joint '{}': its position is not finite", name));
  coupling.geometry.point = exact(geometry.point);
  const auto direction = [&](const std::optional<Eigen::Vector3d>& v, const char* what) -> std::optional<screw::Vec3> {
    if (!v) return std::nullopt;
    if (!v->allFinite() || !(v->norm() > 0)) throw InputError(where, fmt::format("joint '{}': the {} is the zero vector", name, what));
    return exact(*v);
  };
  coupling.geometry.axis = direction(geometry.axis, "axis");
  coupling.geometry.axis2 = direction(geometry.axis2, "second axis");
  coupling.geometry.normal = direction(geometry.normal, "plane normal");
  const double pitch = geometry.pitch;
  if (pitch != 0.0) {
    const std::string text = fmt::format("{}", pitch);
    digits_ = std::max(digits_, significant_digits(text));
    const auto decimal = parse_exact_decimal(text);
    coupling.geometry.pitch = decimal ? *decimal : screw::Rational(pitch);
  }
  try {
    (void)screw::coupling_basis(coupling.type, coupling.geometry, loaded_.model.space);
  } catch (const screw::GeometryError& error) {
    throw InputError(where, fmt::format("joint '{}': {}", name, error.what()));
  }
  loaded_.item_locations["couplings"].push_back(where);
  coupling_names_.insert(name);
  loaded_.model.couplings.push_back(std::move(coupling));
}

void NetworkBuilder::float_base(const std::string& base, const SourceLocation& where) {
  const std::string world = bodies_.count("world") ? "world (ground)" : "world";
  set_ground(world);
  couple(base + " (floating base)", screw::CouplingType::free, world, base, JointGeometry{}, where);
}

std::string NetworkBuilder::mount_loose_groups(bool grounded) {
  // Groups of bodies joined by couplings (union-find over the coupling list).
  const std::size_t n = loaded_.model.bodies.size();
  std::vector<std::size_t> group(n);
  for (std::size_t b = 0; b < n; ++b) group[b] = b;
  const auto find = [&](std::size_t b) {
    while (group[b] != b) b = group[b] = group[group[b]];
    return b;
  };
  for (const network::Coupling& c : loaded_.model.couplings)
    group[find(static_cast<std::size_t>(c.from))] = find(static_cast<std::size_t>(c.to));
  if (!loaded_.model.ground) return {};
  std::vector<std::string> mounted;
  std::vector<bool> done(n, false);
  const auto ground = static_cast<std::size_t>(*loaded_.model.ground);
  done[find(ground)] = true;
  const std::string ground_name = loaded_.model.bodies[ground];
  const SourceLocation at{path_, 0, 0};
  for (std::size_t b = 0; b < n; ++b) {  // bodies in file order: each group at its first body
    const std::size_t g = find(b);
    if (done[g]) continue;
    done[g] = true;
    const std::string body_name = loaded_.model.bodies[b];
    couple(body_name + (grounded ? " (grounded)" : " (floating)"), grounded ? screw::CouplingType::rigid : screw::CouplingType::free,
           ground_name, body_name, JointGeometry{}, at);
    mounted.push_back(body_name);
  }
  if (mounted.empty()) return {};
  std::string names;
  for (std::size_t k = 0; k < mounted.size() && k < 8; ++k) names += (k ? ", '" : "'") + mounted[k] + "'";
  if (mounted.size() > 8) names += fmt::format(" and {} more", mounted.size() - 8);
  return fmt::format("{}: note: {} link(s) or group(s) of links joined to nothing else ({}) {}", path_, mounted.size(), names,
                     grounded ? "welded to the ground, as --base fixed asks (a rigid coupling each)"
                              : "float (a free coupling to the ground each), as in a simulator; --base fixed welds them to the ground");
}

LoadedNetwork NetworkBuilder::finish() {
  if (loaded_.model.couplings.empty()) throw InputError({path_, 0, 0}, "the model has no joints between links (one link alone: --base floating lets it float)");
  loaded_.model.max_significant_digits = digits_;
  loaded_.field_locations["couplings"] = {path_, 0, 0};
  return std::move(loaded_);
}

}  // namespace kinestat::io
