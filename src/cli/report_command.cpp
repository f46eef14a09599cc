// SPDX-License-Identifier: BSD-3-Clause
// `kinestat report FILE -o report.html`: one self-contained interactive HTML report.

#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cli/option_checks.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/report/html_writer.hpp"
#include "kinestat/report/structure_report.hpp"
#include "kinestat/report/svg_writer.hpp"

namespace kinestat::cli {

void register_report(CLI::App& app, Action& action) {
  auto options = std::make_shared<CommonOptions>();
  auto misfit = std::make_shared<std::vector<std::string>>();  // `--misfit` (issue 38): frameworks with elastic data
  CLI::App* command = app.add_subcommand(
      "report", "Write a self-contained interactive HTML report (summary, 3D view, modes, self-stress)");
  command->add_option("model", options->model_path, "Model file of any kind: kinestat YAML / JSON, SPACAR .dat, URDF .urdf, SDFormat .sdf or MJCF .xml; '-': kinestat YAML / JSON on standard input")->required();
  command->add_option("-o,--output", options->output_path, "Write the HTML to this file instead of standard output");
  command->add_option("--tolerance", options->tolerance, "Relative rank tolerance (as for analyze)")->check(positive_finite_number());
  add_misfit_option(*command, *misfit,
                    "Frameworks with materials and sections: a manufacturing misfit (model length unit); the view shows "
                    "the stress the worst one locks into the elements (default: per unit of misfit)");
  command->callback([options, misfit, &action] {
    action = [options, misfit] {
      // The model first: a bad model is reported as such whether or not the viewer is built in.
      const pipeline::ModelPictures loaded =
          load_scene(options->model_path, options->tolerance, /*traced_motion=*/true, misfit_tolerance(*misfit));
      if (!report::html_report_built_in()) {
        std::cerr << "kinestat: error: HTML output is not built in: this kinestat was built without npm, so three.js "
                     "could not be embedded (rebuild with npm available; 'kinestat draw' writes SVG)\n";
        return 2;
      }
      std::string figure, title;
      if (loaded.kind == io::ModelKind::network && !loaded.scene.large) {
        figure = report::graph_svg(loaded.scene);
        title = "Coupling, motion and action graphs";
      } else if (loaded.kind == io::ModelKind::structure && loaded.decomposition && !loaded.scene.large) {
        figure = report::structure_svg(*loaded.structure_model, *loaded.decomposition);
        title = "Structural diagram";
      }
      emit(*options, report::html_report(loaded.scene, figure, title));
      return 0;
    };
  });
}

}  // namespace kinestat::cli
