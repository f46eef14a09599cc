// SPDX-License-Identifier: BSD-3-Clause
// Stiffness, eigenpairs and the misfit cost of a framework as numpy arrays (issue 38, item 5):
// methods of kinestat._core.Analysed, bound by bind_stiffness (declared in analysed.hpp).

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

#include "analysed.hpp"
#include "kinestat/framework/geometric_stiffness.hpp"
#include "kinestat/framework/misfit.hpp"
#include "kinestat/framework/over_constraint_cost.hpp"
#include "kinestat/framework/stiffness.hpp"
#include "kinestat/report/json_text.hpp"
#include "kinestat/report/stiffness_report.hpp"

namespace kinestat::python {

namespace py = pybind11;

namespace {

const framework::FrameworkModel& elastic_framework_of(const Analysed& a) {
  if (!a.file.framework || !a.analysis.framework) throw py::value_error("not a framework result");
  if (!a.file.framework->has_elastic_data())
    throw py::value_error("the model has no elastic data (materials, sections, masses: docs/stiffness.md)");
  return *a.file.framework;
}

std::size_t node_index(const framework::FrameworkModel& model, const std::string& name) {
  for (std::size_t n = 0; n < model.nodes.size(); ++n)
    if (model.nodes[n].name == name) return n;
  throw py::value_error("no node named '" + name + "' in the model");
}

/// A misfit as Python gives it (model length unit): one number for every element, or a dict
/// {element name: misfit} for the elements named (the others none), as `--misfit VALUE` and
/// `--misfit ELEMENT=VALUE` on the command line.
using MisfitArgument = std::variant<double, std::map<std::string, double>>;

/// The misfit of every element of `model` that `misfit` gives. ValueError for a length that is
/// negative or not finite, or an element the model does not have (named in the message).
framework::MisfitTolerance misfit_tolerance(const framework::FrameworkModel& model, const MisfitArgument& misfit) {
  const auto check = [](double length, const std::string& of) {
    if (!(length >= 0.0) || !std::isfinite(length))
      throw py::value_error("misfit" + of + " must be a finite length, zero or more, not " +
                            py::str(py::float_(length)).cast<std::string>());
  };
  framework::MisfitTolerance tolerance;
  if (const double* plain = std::get_if<double>(&misfit)) {
    check(*plain, "");
    tolerance.value = *plain;
    return tolerance;
  }
  tolerance.per_element = std::get<std::map<std::string, double>>(misfit);
  for (const auto& [element, length] : tolerance.per_element) check(length, " of element '" + element + "'");
  if (const std::optional<std::string> unknown = framework::unknown_misfit_element(model, tolerance))
    throw py::value_error("misfit: the model has no element named '" + *unknown + "'");
  return tolerance;
}

// std::invalid_argument from the stiffness code (no elastic element at a node, a rigid loop)
// becomes Python's ValueError.
template <typename F>
auto as_value_error(F&& f) {
  try {
    return f();
  } catch (const std::invalid_argument& error) {
    throw py::value_error(error.what());
  }
}

}  // namespace

void bind_stiffness(AnalysedClass& cls) {
  cls.def(
         "stiffness_matrix",
         [](const Analysed& a) {
           const framework::FrameworkModel& model = elastic_framework_of(a);
           return as_value_error([&] {
             const framework::FrameworkStiffness assembled = framework::assemble_stiffness(model);
             return std::make_tuple(Eigen::MatrixXd(assembled.stiffness), assembled.labels);
           });
         },
         "K = Dᵀ K_ε D over the free coordinates (model units) and their labels 'NODE.slot'")
      .def(
          "eigenpairs",
          [](const Analysed& a, const MisfitArgument& misfit) {
            const framework::FrameworkModel& model = elastic_framework_of(a);
            const framework::MisfitTolerance tolerance = misfit_tolerance(model, misfit);
            return as_value_error([&] {
              const framework::FrameworkStiffness assembled = framework::assemble_stiffness(model);
              Eigen::MatrixXd prestress;
              if (tolerance.value.value_or(0.0) != 0.0 || !tolerance.per_element.empty()) {
                const framework::MisfitResult m =
                    framework::analyse_misfit(model, a.analysis.framework->result, framework::element_compliance(model), tolerance);
                prestress = framework::prestress_geometric_stiffness(model, assembled.indexing, m.worst_resultants);
              }
              const std::optional<framework::VibrationModes> modes = framework::framework_vibration(model, assembled, prestress);
              if (!modes) throw py::value_error("the model gives no masses: no eigenfrequencies");
              return std::make_tuple(modes->frequencies, modes->shapes, assembled.labels);
            });
          },
          py::arg("misfit") = 0.0,
          "Eigenfrequencies (Hz, ascending), mass-normalised mode shapes (columns over the free "
          "coordinates) and the coordinate labels; with `misfit` (a length, or a dict {element: length}), "
          "under the worst misfit's prestress")
      .def(
          "over_constraint",
          [](const Analysed& a, const std::string& at, const MisfitArgument& misfit) {
            const framework::FrameworkModel& model = elastic_framework_of(a);
            const framework::MisfitTolerance tolerance = misfit_tolerance(model, misfit);
            return as_value_error([&] {
              const framework::OverConstraintCost cost =
                  framework::over_constraint_cost(model, a.analysis.framework->result, node_index(model, at), tolerance);
              return report::json_text(report::over_constraint_json(model, cost));
            });
          },
          py::arg("at"), py::arg("misfit"),
          "The `misfit` and `frequencies` keys of `kinestat stiffness --misfit` as JSON text; `misfit` a length or a "
          "dict {element: length} (`--misfit ELEMENT=VALUE`)");
}

}  // namespace kinestat::python
