// The `curvebench` command line as a function, so that a program built on the installed
// library (curvebench_add_program, docs/own-algorithm.md) has every verb of it.
#include "bench/cli/program.h"

#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

#include "bench/cli/ambiguity_command.h"
#include "bench/cli/annotate_command.h"
#include "bench/cli/certify_command.h"
#include "bench/cli/evaluate_command.h"
#include "bench/cli/graph_command.h"
#include "bench/cli/hunt_command.h"
#include "bench/cli/image_command.h"
#include "bench/cli/list_command.h"
#include "bench/cli/make_input_command.h"
#include "bench/cli/measure_command.h"
#include "bench/cli/perturb_commands.h"
#include "bench/cli/rate_command.h"
#include "bench/cli/reconstruct_command.h"
#include "bench/cli/run_command.h"
#include "bench/cli/sample_command.h"
#include "bench/cli/slurm_command.h"
#include "bench/cli/tightness_command.h"

namespace curvebench::cli {

int run_command_line(int argc, char** argv) {
  CLI::App app{"curvebench: planar curve reconstruction on exact geometry"};
  app.require_subcommand(1);
  add_graph_command(app);
  add_list_command(app);
  add_reconstruct_command(app);
  add_rate_command(app);
  add_sample_command(app);
  add_noise_command(app);
  add_outliers_command(app);
  add_measure_command(app);
  add_rasterize_command(app);
  add_image_sample_command(app);
  add_run_commands(app);
  add_evaluate_command(app);
  add_certify_command(app);
  add_ambiguity_command(app);
  add_hunt_command(app);
  add_annotate_command(app);
  add_make_input_command(app);
  add_slurm_command(app);
  add_tightness_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    // ParseError messages already start with "FILE:LINE:"; everything else gets our name.
    std::cerr << "curvebench: " << e.what() << '\n';
    return 2;
  }
  return 0;
}

}  // namespace curvebench::cli
