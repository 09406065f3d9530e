// The `curvebench` command: one subcommand per job, each in its own file.
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

int main(int argc, char** argv) {
  CLI::App app{"curvebench: planar curve reconstruction on exact geometry"};
  app.require_subcommand(1);
  curvebench::cli::add_graph_command(app);
  curvebench::cli::add_list_command(app);
  curvebench::cli::add_reconstruct_command(app);
  curvebench::cli::add_rate_command(app);
  curvebench::cli::add_sample_command(app);
  curvebench::cli::add_noise_command(app);
  curvebench::cli::add_outliers_command(app);
  curvebench::cli::add_measure_command(app);
  curvebench::cli::add_rasterize_command(app);
  curvebench::cli::add_image_sample_command(app);
  curvebench::cli::add_run_commands(app);
  curvebench::cli::add_evaluate_command(app);
  curvebench::cli::add_certify_command(app);
  curvebench::cli::add_ambiguity_command(app);
  curvebench::cli::add_hunt_command(app);
  curvebench::cli::add_annotate_command(app);
  curvebench::cli::add_make_input_command(app);
  curvebench::cli::add_slurm_command(app);
  curvebench::cli::add_tightness_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    // ParseError messages already start with "FILE:LINE:"; everything else gets our name.
    std::cerr << "curvebench: " << e.what() << '\n';
    return 2;
  }
}
