#pragma once
// The JSON report of a framework or network model as `kinestat analyze --json MODEL` prints it
// with its default options: the analysis, the generic answer, the verdict and the report, in
// one pure function (the sweep runs it on every variant).

#include <nlohmann/json.hpp>

#include <optional>

#include "kinestat/io/model_file.hpp"

namespace kinestat::report {

/// The report of `model` (a framework or a network; a structure model is an InputError) with the
/// relative rank tolerance `tolerance` (default: the LAPACK rule, as `--tolerance`). Networks
/// above network::kDenseNetworkLimit couplings take the sparse path, as `analyze` does. A
/// problem the analysis finds in the model is an InputError at its place in `model.path`.
nlohmann::ordered_json analysis_report_json(const io::ModelFile& model, std::optional<double> tolerance = {});

}  // namespace kinestat::report
