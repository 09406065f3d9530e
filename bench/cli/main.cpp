// The `curvebench` program, and the main of every program curvebench_add_program builds:
// the command line, with the bundled data and report scripts found where this program
// is installed, else at CURVEBENCH_RESOURCE_ROOT (the source tree, or the installed
// package that a user's program was built against).
#include "bench/cli/program.h"
#include "bench/runner/huge_page_malloc.h"
#include "bench/runner/resources.h"

int main(int argc, char** argv) {
  curvebench::bench::restart_with_huge_page_malloc(argv);
  curvebench::bench::set_resource_root(curvebench::bench::installed_root_or(CURVEBENCH_RESOURCE_ROOT));
  return curvebench::cli::run_command_line(argc, argv);
}
