// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// kinestat's public API: the entry points a program needs. Only these headers and the kinestat
// headers they include are installed (src/kinestat/CMakeLists.txt follows the includes); the rest
// of the library is internal. Layers: screw, graph, linalg -> network, framework, structure,
// kinematics, design -> io -> report -> pipeline (docs/architecture.md, docs/cpp.md).
//
//   const kinestat::io::ModelFile file = kinestat::io::read_model_file("examples/bennett.yaml");
//   const kinestat::pipeline::ModelAnalysis analysis = kinestat::pipeline::analyse_model(file);
//   analysis.verdict().summary;                              // one sentence
//   kinestat::pipeline::report_json_text(file, analysis);    // what `kinestat analyze --json` prints

// Errors and tolerances.
#include "kinestat/error.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/stop_request.hpp"
#include "kinestat/tolerances.hpp"
// Models, and reading them from files of every format.
#include "kinestat/framework/framework_model.hpp"
#include "kinestat/io/model_file.hpp"
#include "kinestat/io/model_kind.hpp"
#include "kinestat/network/model.hpp"
#include "kinestat/structure/structure_model.hpp"
// Analysis: read -> plan -> analyse -> verdict, as the `kinestat` commands do.
#include "kinestat/pipeline/model_pipeline.hpp"
// The verdict and the reports.
#include "kinestat/design/verdict.hpp"
#include "kinestat/report/framework_report.hpp"
#include "kinestat/report/json_text.hpp"
#include "kinestat/report/network_report.hpp"
#include "kinestat/report/structure_report.hpp"
#include "kinestat/report/verdict_report.hpp"
