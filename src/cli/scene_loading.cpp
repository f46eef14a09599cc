// SPDX-License-Identifier: BSD-3-Clause
// Reads a model of any kind and has the pipeline analyse it into the scene that `draw` and
// `report` picture.

#include "cli/commands.hpp"
#include "kinestat/io/model_file.hpp"
#include "kinestat/pipeline/model_pipeline.hpp"

namespace kinestat::cli {

io::ModelKind model_kind_of(const io::YamlFile& file) {
  // io::model_kind accepts only the three spellings (anything else is an InputError there).
  return io::kind_named(io::model_kind(file)).value();
}

pipeline::ModelPictures load_scene(const std::string& path, std::optional<double> tolerance, bool traced_motion,
                                   const std::optional<framework::MisfitTolerance>& misfit) {
  return pipeline::picture_model(read_model(path), tolerance, traced_motion, misfit);  // any format, notices on stderr
}

}  // namespace kinestat::cli
