// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A model read and analysed as the Python module holds it (kinestat._core.Analysed), and the
// pybind11 class it is bound as. Each kind of result is bound by one function taking that class
// (core_module.cpp: bind_reports, bind_network, bind_framework_counts, ...). A further kind (for
// example stiffness) is bound in its own file by a `void bind_<kind>(AnalysedClass&)` declared
// here and called from PYBIND11_MODULE, where core_module.cpp leaves its place.

#include <pybind11/pybind11.h>

#include <memory>

#include "kinestat/design/verdict.hpp"
#include "kinestat/io/model_file.hpp"
#include "kinestat/pipeline/model_pipeline.hpp"
#include "kinestat/report/scene.hpp"

namespace kinestat::python {

/// A model file read, and its analysis once run (pipeline::analyse_model or decompose_model).
/// Results keep their model alive.
struct Analysed {
  io::ModelFile file;
  pipeline::ModelAnalysis analysis;

  const design::Verdict& verdict() const { return analysis.verdict(); }
  /// The scene of `kinestat draw` and `kinestat report`; with `traced_motion`, frameworks carry
  /// their finite modes traced both ways, as the report does.
  report::Scene scene(bool traced_motion = false) const { return pipeline::model_scene(file, analysis, traced_motion); }
};

/// The Python class of Analysed (shared: a result keeps its model alive past the call).
using AnalysedClass = pybind11::class_<Analysed, std::shared_ptr<Analysed>>;

/// Stiffness matrix, eigenpairs and the misfit cost of a framework with elastic data
/// (stiffness_bindings.cpp).
void bind_stiffness(AnalysedClass& cls);

}  // namespace kinestat::python
