// SPDX-License-Identifier: BSD-3-Clause
#include "model_transforms.hpp"

#include <algorithm>
#include <numeric>
#include <random>
#include <stdexcept>

#include "kinestat/io/network_reader.hpp"
#include "kinestat/io/yaml_support.hpp"

namespace kinestat::mechanisms_test {

namespace {

screw::Vec3 times(const Matrix3& r, const screw::Vec3& v) {
  screw::Vec3 out{0, 0, 0};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) out[i] += r[i][j] * v[j];
  return out;
}

screw::Vec3 plus(const screw::Vec3& a, const screw::Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }

std::array<Rational, 6> embed(const std::vector<Rational>& coordinates, const screw::ScrewSpace& space) {
  std::array<Rational, 6> full{0, 0, 0, 0, 0, 0};
  for (std::size_t i = 0; i < space.components.size(); ++i)
    full[static_cast<std::size_t>(space.components[i])] = coordinates[i];
  return full;
}

std::vector<Rational> project(const std::array<Rational, 6>& full, const screw::ScrewSpace& space) {
  std::vector<Rational> out;
  for (int c : space.components) out.push_back(full[static_cast<std::size_t>(c)]);
  return out;
}

// A motion (w; v) or an action (m; f) after the rigid motion p -> R p + t.
std::vector<Rational> move_motion(const std::vector<Rational>& s, const screw::ScrewSpace& space, const Matrix3& r,
                                  const screw::Vec3& t) {
  const auto full = embed(s, space);
  const screw::Vec3 w = times(r, {full[0], full[1], full[2]});
  const screw::Vec3 v = plus(times(r, {full[3], full[4], full[5]}), screw::cross(t, w));
  return project({w[0], w[1], w[2], v[0], v[1], v[2]}, space);
}

std::vector<Rational> move_action(const std::vector<Rational>& s, const screw::ScrewSpace& space, const Matrix3& r,
                                  const screw::Vec3& t) {
  const auto full = embed(s, space);
  const screw::Vec3 f = times(r, {full[3], full[4], full[5]});
  const screw::Vec3 m = plus(times(r, {full[0], full[1], full[2]}), screw::cross(t, f));
  return project({m[0], m[1], m[2], f[0], f[1], f[2]}, space);
}

Rational to_double_and_back(const Rational& x) { return Rational(x.get_d()); }

}  // namespace

std::string example_path(const std::string& file) { return std::string(KINESTAT_SOURCE_DIR) + "/examples/" + file; }

network::Model load_example(const std::string& file) {
  return io::read_network_model(io::YamlFile::load(example_path(file))).model;
}

Matrix3 quaternion_rotation(long w, long x, long y, long z) {
  const Rational n = w * w + x * x + y * y + z * z;
  const auto q = [&](long v) { return Rational(v); };
  Matrix3 r{{{q(w * w + x * x - y * y - z * z), q(2 * (x * y - w * z)), q(2 * (x * z + w * y))},
             {q(2 * (x * y + w * z)), q(w * w - x * x + y * y - z * z), q(2 * (y * z - w * x))},
             {q(2 * (x * z - w * y)), q(2 * (y * z + w * x)), q(w * w - x * x - y * y + z * z)}}};
  for (auto& row : r)
    for (auto& e : row) e /= n;
  return r;
}

Matrix3 z_rotation(const Rational& c, const Rational& s) { return {{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}}; }

network::Model rigidly_moved(network::Model model, const Matrix3& rotation, const screw::Vec3& translation) {
  for (auto& c : model.couplings) {
    auto& g = c.geometry;
    g.point = plus(times(rotation, g.point), translation);
    if (g.axis) g.axis = times(rotation, *g.axis);
    if (g.axis2) g.axis2 = times(rotation, *g.axis2);
    if (g.normal) g.normal = times(rotation, *g.normal);
    for (auto& m : g.custom_motions) m = move_motion(m, model.space, rotation, translation);
    for (auto& a : g.custom_actions) a = move_action(a, model.space, rotation, translation);
  }
  model.primary.clear();
  model.values.clear();
  return model;
}

network::Model scaled(network::Model model, const Rational& factor) {
  for (auto& c : model.couplings) {
    auto& g = c.geometry;
    g.point = screw::scaled(g.point, factor);
    g.pitch *= factor;
    // Lengths times `factor`: velocities of points (motions) and moments (actions) scale.
    for (auto& m : g.custom_motions) {
      auto full = embed(m, model.space);
      for (std::size_t i = 3; i < 6; ++i) full[i] *= factor;
      m = project(full, model.space);
    }
    for (auto& a : g.custom_actions) {
      auto full = embed(a, model.space);
      for (std::size_t i = 0; i < 3; ++i) full[i] *= factor;
      a = project(full, model.space);
    }
  }
  // Primary motions keep their names; their values would change units, so drop them.
  model.values.clear();
  return model;
}

network::Model renamed_and_reordered(network::Model model, unsigned seed) {
  std::mt19937 random(seed);
  const std::size_t n = model.bodies.size();
  std::vector<std::size_t> body_order(n);
  std::iota(body_order.begin(), body_order.end(), std::size_t{0});
  std::shuffle(body_order.begin(), body_order.end(), random);
  std::vector<int> new_index(n);
  std::vector<std::string> bodies(n);
  for (std::size_t i = 0; i < n; ++i) {
    bodies[i] = "b" + model.bodies[body_order[i]];
    new_index[body_order[i]] = static_cast<int>(i);
  }
  std::vector<network::Coupling> couplings = model.couplings;
  std::shuffle(couplings.begin(), couplings.end(), random);
  for (std::size_t i = 0; i < couplings.size(); ++i) {
    auto& c = couplings[i];
    c.name = "c" + c.name;
    c.from = new_index[static_cast<std::size_t>(c.from)];
    c.to = new_index[static_cast<std::size_t>(c.to)];
    if (i % 2 == 1) std::swap(c.from, c.to);
  }
  model.bodies = bodies;
  model.couplings = couplings;
  model.ground = new_index[static_cast<std::size_t>(model.ground.value_or(0))];
  for (auto& chord : model.chords) chord = "c" + chord;
  model.primary.clear();
  model.values.clear();
  return model;
}

network::Model with_random_tree(network::Model model, unsigned seed) {
  model.chords.clear();
  model.primary.clear();
  model.values.clear();
  if (seed == 0) return model;
  std::mt19937 random(seed);
  std::vector<std::size_t> order(model.couplings.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::shuffle(order.begin(), order.end(), random);
  std::vector<std::size_t> parent(model.bodies.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const auto find = [&](std::size_t b) {
    while (parent[b] != b) b = parent[b] = parent[parent[b]];
    return b;
  };
  for (std::size_t e : order) {
    const std::size_t a = find(static_cast<std::size_t>(model.couplings[e].from));
    const std::size_t b = find(static_cast<std::size_t>(model.couplings[e].to));
    if (a == b) model.chords.push_back(model.couplings[e].name);
    else parent[a] = b;
  }
  return model;
}

network::Model rounded_to_double(network::Model model) {
  const auto round3 = [](screw::Vec3& v) {
    for (auto& x : v) x = to_double_and_back(x);
  };
  for (auto& c : model.couplings) {
    auto& g = c.geometry;
    round3(g.point);
    if (g.axis) round3(*g.axis);
    if (g.axis2) round3(*g.axis2);
    if (g.normal) round3(*g.normal);
    g.pitch = to_double_and_back(g.pitch);
    for (auto& m : g.custom_motions)
      for (auto& x : m) x = to_double_and_back(x);
    for (auto& a : g.custom_actions)
      for (auto& x : a) x = to_double_and_back(x);
  }
  model.max_significant_digits = std::max(model.max_significant_digits, 16);
  return model;
}

std::string original_name(const std::string& renamed) { return renamed.substr(1); }

std::map<PairKey, std::pair<int, int>> pair_table(const network::Model& model, const network::NetworkResult& result,
                                                   bool undo_renaming) {
  const auto name = [&](const std::string& s) { return undo_renaming ? original_name(s) : s; };
  std::map<PairKey, std::pair<int, int>> table;
  for (const auto& p : result.pairs) {
    std::string a = name(model.bodies[static_cast<std::size_t>(p.body_i)]);
    std::string b = name(model.bodies[static_cast<std::size_t>(p.body_j)]);
    if (b < a) std::swap(a, b);
    const std::string coupling = p.coupling ? name(model.couplings[static_cast<std::size_t>(*p.coupling)].name) : "";
    const auto [it, inserted] = table.emplace(PairKey{a, b, coupling}, std::make_pair(p.fij, p.cij));
    if (!inserted) throw std::logic_error("pair listed twice: " + a + ", " + b + ", " + coupling);
  }
  return table;
}

std::map<PairKey, std::pair<std::vector<std::string>, std::vector<std::string>>> pair_primaries(
    const network::Model& model, const network::NetworkResult& result) {
  std::map<PairKey, std::pair<std::vector<std::string>, std::vector<std::string>>> table;
  for (const auto& p : result.pairs) {
    std::string a = model.bodies[static_cast<std::size_t>(p.body_i)];
    std::string b = model.bodies[static_cast<std::size_t>(p.body_j)];
    if (b < a) std::swap(a, b);
    const std::string coupling = p.coupling ? model.couplings[static_cast<std::size_t>(*p.coupling)].name : "";
    auto& row = table[PairKey{a, b, coupling}];
    for (int m : p.motion_primaries)
      row.first.push_back(result.motions[static_cast<std::size_t>(result.primary_motion[static_cast<std::size_t>(m)])].name);
    for (int m : p.action_primaries)
      row.second.push_back(result.actions[static_cast<std::size_t>(result.primary_action[static_cast<std::size_t>(m)])].name);
  }
  return table;
}

int fij(const network::Model& model, const network::NetworkResult& result, const std::string& a, const std::string& b) {
  for (const auto& p : result.pairs) {
    const std::string& i = model.bodies[static_cast<std::size_t>(p.body_i)];
    const std::string& j = model.bodies[static_cast<std::size_t>(p.body_j)];
    if ((i == a && j == b) || (i == b && j == a)) return p.fij;
  }
  throw std::logic_error("no pair " + a + ", " + b);
}

int cij(const network::Model& model, const network::NetworkResult& result, const std::string& coupling) {
  for (const auto& p : result.pairs)
    if (p.coupling && model.couplings[static_cast<std::size_t>(*p.coupling)].name == coupling) return p.cij;
  throw std::logic_error("no coupling " + coupling);
}

int magnitude_index(const std::vector<network::Magnitude>& magnitudes, const std::string& name) {
  for (std::size_t i = 0; i < magnitudes.size(); ++i)
    if (magnitudes[i].name == name) return static_cast<int>(i);
  throw std::logic_error("no magnitude " + name);
}

}  // namespace kinestat::mechanisms_test
