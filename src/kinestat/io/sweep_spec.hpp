// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reads a sweep spec (`kind: sweep`, docs/sweep.md): the model and the parameters varied in it,
// or a list of variant files. Every problem is an InputError at its place in the spec
// (file:line:column: what was expected). Only the spec is read here: where each parameter
// stands in the model is found by io::prepare_sweep_model (sweep_model.hpp).

#include <cstdint>
#include <string>
#include <vector>

#include "kinestat/io/input_error.hpp"

namespace kinestat::io {

/// One swept number of the model.
struct SweepParameter {
  std::string name;               ///< the key of its value in every line's `parameters`
  std::vector<std::string> path;  ///< steps from the model's root to the number (see docs/sweep.md)
  std::string address;            ///< how the spec addresses it, for messages: "node A1, coordinate z"
  std::vector<double> values;     ///< the values it takes, in the model's units, in order
  SourceLocation where;           ///< the parameter's entry in the spec
};

/// A sweep spec as written. Exactly one of `model` (with `parameters`) and `variants` is set.
struct SweepSpec {
  std::string path;   ///< the spec file, as given
  std::string model;  ///< the model file as the spec writes it (relative to the spec's folder)
  SourceLocation model_where;
  std::vector<SweepParameter> parameters;  ///< the grid's axes, the first varying slowest
  std::vector<std::string> variants;       ///< variant files as written (relative to the spec's folder)
  std::vector<SourceLocation> variant_where;
  std::uint64_t count = 0;  ///< number of variants (product of the parameters' sizes, or of the files)
};

/// Reads the spec from `text` (YAML or JSON; checks `kinestat: 1` and `kind: sweep`); `path` names
/// it in messages and is the folder its paths are relative to.
SweepSpec parse_sweep_spec(const std::string& path, const std::string& text);
/// Reads the spec file at `path` (bounded, as model files; "-": standard input, named "<stdin>").
SweepSpec read_sweep_spec(const std::string& path);

/// `written` (a path in the spec) as a path from the working directory: unchanged when absolute,
/// otherwise relative to the folder of the spec file `spec_path`.
std::string spec_relative_path(const std::string& spec_path, const std::string& written);

}  // namespace kinestat::io
