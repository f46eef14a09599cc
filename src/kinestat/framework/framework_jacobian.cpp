// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/framework/framework_jacobian.hpp"

#include "kinestat/framework/deformation_functions.hpp"

namespace kinestat::framework {

namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

// Scatters a local derivative block (rows: selected local deformations; columns: slots 0..5 of
// each listed node in turn) into global triplets, skipping slots the node does not have.
void scatter(Triplets& out, const FrameworkIndexing& indexing, Eigen::Index first_row,
             const Eigen::Ref<const Eigen::MatrixXd>& local, const std::vector<int>& local_rows,
             const std::vector<std::size_t>& nodes, int slots_per_node) {
  for (std::size_t r = 0; r < local_rows.size(); ++r) {
    for (std::size_t n = 0; n < nodes.size(); ++n) {
      for (int slot = 0; slot < slots_per_node; ++slot) {
        const Eigen::Index column = indexing.coordinate_of[nodes[n]][static_cast<std::size_t>(slot)];
        const double value = local(local_rows[r], static_cast<Eigen::Index>(n) * slots_per_node + slot);
        if (column >= 0 && value != 0.0) out.emplace_back(first_row + static_cast<Eigen::Index>(r), column, value);
      }
    }
  }
}

}  // namespace

FrameworkIndexing index_framework(const FrameworkModel& model) {
  FrameworkIndexing indexing;
  indexing.coordinate_of.resize(model.nodes.size());
  for (std::size_t n = 0; n < model.nodes.size(); ++n) {
    indexing.coordinate_of[n].fill(-1);
    for (int slot : node_slots(model.dimension, model.nodes[n])) {
      indexing.coordinate_of[n][static_cast<std::size_t>(slot)] = static_cast<Eigen::Index>(indexing.coordinates.size());
      indexing.coordinates.push_back({n, slot});
    }
  }
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    indexing.first_deformation.push_back(static_cast<Eigen::Index>(indexing.deformations.size()));
    const std::size_t count = deformation_count(model.dimension, model.elements[e]);
    for (std::size_t k = 0; k < count; ++k) indexing.deformations.push_back({e, k});
  }
  return indexing;
}

DisplacedConfiguration analysed_configuration(const FrameworkModel& model) {
  DisplacedConfiguration configuration;
  for (const Node& node : model.nodes) configuration.positions.push_back(node.position);
  configuration.turns.assign(model.nodes.size(), Eigen::Matrix3d::Identity());
  return configuration;
}

BeamConfiguration beam_at(const FrameworkModel& model, const Element& element, const DisplacedConfiguration& configuration) {
  BeamConfiguration beam;
  beam.xp = configuration.positions[element.nodes[0]];
  beam.xq = configuration.positions[element.nodes[1]];
  beam.triad_p = configuration.turns[element.nodes[0]] * element.frame;
  beam.triad_q = configuration.turns[element.nodes[1]] * element.frame;
  beam.l0 = (model.nodes[element.nodes[1]].position - model.nodes[element.nodes[0]].position).norm();
  beam.torsion_coupling = element.torsion_coupling;
  return beam;
}

Eigen::SparseMatrix<double> deformation_derivative(const FrameworkModel& model, const FrameworkIndexing& indexing) {
  return deformation_derivative_at(model, indexing, analysed_configuration(model));
}

Eigen::SparseMatrix<double> deformation_derivative_at(const FrameworkModel& model, const FrameworkIndexing& indexing,
                                                      const DisplacedConfiguration& configuration) {
  Triplets triplets;
  const bool planar = model.dimension == 2;
  const auto& x = configuration.positions;
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const Element& element = model.elements[e];
    const Eigen::Index row = indexing.first_deformation[e];
    switch (element.type) {
      case ElementType::truss: {
        scatter(triplets, indexing, row, truss_elongation_derivative(x[element.nodes[0]], x[element.nodes[1]]), {0}, element.nodes, 3);
        break;
      }
      case ElementType::beam: {
        const BeamConfiguration beam = beam_at(model, element, configuration);
        // A planar beam keeps the in-plane deformations of the spatial one: elongation and
        // bending in the local xy-plane (local z is the global z axis).
        const std::vector<int> rows = planar ? std::vector<int>{0, 4, 5} : std::vector<int>{0, 1, 2, 3, 4, 5};
        scatter(triplets, indexing, row, beam_deformation_derivative(beam), rows, element.nodes, 6);
        break;
      }
      case ElementType::rigid_body: {
        const std::size_t reference = element.nodes[0];
        const std::vector<int> rows = planar ? std::vector<int>{0, 1, 5} : std::vector<int>{0, 1, 2, 3, 4, 5};
        // Relative coordinates in the reference node's axes as analysed: turned back by its turn.
        Eigen::Matrix<double, 6, 6> back = Eigen::Matrix<double, 6, 6>::Zero();
        back.topLeftCorner<3, 3>() = back.bottomRightCorner<3, 3>() = configuration.turns[reference].transpose();
        for (std::size_t k = 1; k < element.nodes.size(); ++k) {
          const Derivative6x12 link = back * rigid_link_derivative(x[reference], x[element.nodes[k]]);
          scatter(triplets, indexing, row + static_cast<Eigen::Index>((k - 1) * rows.size()), link, rows,
                  {reference, element.nodes[k]}, 6);
        }
        break;
      }
    }
  }
  Eigen::SparseMatrix<double> derivative(static_cast<Eigen::Index>(indexing.deformations.size()),
                                         static_cast<Eigen::Index>(indexing.coordinates.size()));
  derivative.setFromTriplets(triplets.begin(), triplets.end());
  return derivative;
}

std::vector<Eigen::Index> FrameworkPartition::jacobian_rows() const {
  std::vector<Eigen::Index> rows = fixed_deformations;
  rows.insert(rows.end(), independent_deformations.begin(), independent_deformations.end());
  return rows;
}

FrameworkPartition partition_framework(const FrameworkModel& model, const FrameworkIndexing& indexing) {
  FrameworkPartition partition;
  for (std::size_t i = 0; i < indexing.coordinates.size(); ++i) {
    const CoordinateRef& c = indexing.coordinates[i];
    const auto index = static_cast<Eigen::Index>(i);
    switch (model.nodes[c.node].roles[static_cast<std::size_t>(c.slot)]) {
      case CoordinateRole::fixed: partition.fixed_coordinates.push_back(index); break;
      case CoordinateRole::dependent: partition.dependent_coordinates.push_back(index); break;
      case CoordinateRole::independent: partition.independent_coordinates.push_back(index); break;
    }
  }
  for (std::size_t i = 0; i < indexing.deformations.size(); ++i) {
    const DeformationRef& d = indexing.deformations[i];
    const auto index = static_cast<Eigen::Index>(i);
    switch (model.elements[d.element].roles[d.deformation]) {
      case DeformationRole::fixed: partition.fixed_deformations.push_back(index); break;
      case DeformationRole::independent: partition.independent_deformations.push_back(index); break;
      case DeformationRole::released: partition.released_deformations.push_back(index); break;
    }
  }
  return partition;
}

ConstraintCount count_constraints(const FrameworkPartition& p) {
  ConstraintCount count;
  count.fixed_coordinates = static_cast<Eigen::Index>(p.fixed_coordinates.size());
  count.dependent_coordinates = static_cast<Eigen::Index>(p.dependent_coordinates.size());
  count.independent_coordinates = static_cast<Eigen::Index>(p.independent_coordinates.size());
  count.coordinates = count.fixed_coordinates + count.dependent_coordinates + count.independent_coordinates;
  count.fixed_deformations = static_cast<Eigen::Index>(p.fixed_deformations.size());
  count.independent_deformations = static_cast<Eigen::Index>(p.independent_deformations.size());
  count.released_deformations = static_cast<Eigen::Index>(p.released_deformations.size());
  return count;
}

Eigen::SparseMatrix<double> dependent_jacobian(const FrameworkModel& model, const FrameworkIndexing& indexing,
                                               const FrameworkPartition& partition,
                                               const Eigen::SparseMatrix<double>& derivative, double length) {
  const std::vector<Eigen::Index> rows = partition.jacobian_rows();
  const auto& columns = partition.dependent_coordinates;
  std::vector<Eigen::Index> row_position(static_cast<std::size_t>(derivative.rows()), -1);
  std::vector<Eigen::Index> column_position(static_cast<std::size_t>(derivative.cols()), -1);
  for (std::size_t i = 0; i < rows.size(); ++i) row_position[static_cast<std::size_t>(rows[i])] = static_cast<Eigen::Index>(i);
  for (std::size_t j = 0; j < columns.size(); ++j)
    column_position[static_cast<std::size_t>(columns[j])] = static_cast<Eigen::Index>(j);

  // Whether each row is a length, found once per row in order (not once per entry).
  std::vector<char> length_row(static_cast<std::size_t>(derivative.rows()), 0);
  for (std::size_t i = 0; i < length_row.size(); ++i) {
    const DeformationRef& d = indexing.deformations[i];
    length_row[i] = deformation_is_length(model.dimension, model.elements[d.element], d.deformation) ? 1 : 0;
  }
  Triplets triplets;
  triplets.reserve(static_cast<std::size_t>(derivative.nonZeros()));
  for (Eigen::Index k = 0; k < derivative.outerSize(); ++k) {
    const Eigen::Index c = column_position[static_cast<std::size_t>(k)];
    if (c < 0) continue;
    const bool translation = is_translation(indexing.coordinates[static_cast<std::size_t>(k)].slot);
    for (Eigen::SparseMatrix<double>::InnerIterator it(derivative, k); it; ++it) {
      const Eigen::Index r = row_position[static_cast<std::size_t>(it.row())];
      if (r < 0) continue;
      double value = it.value();
      if (translation) value *= length;
      if (length_row[static_cast<std::size_t>(it.row())] != 0) value /= length;
      triplets.emplace_back(r, c, value);
    }
  }
  Eigen::SparseMatrix<double> jacobian(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(columns.size()));
  jacobian.setFromTriplets(triplets.begin(), triplets.end());
  return jacobian;
}

}  // namespace kinestat::framework
