#include "bench/cli/hunt_command.h"

#include <iostream>
#include <memory>

#include "bench/cli/algorithm_options.h"
#include "bench/runner/hunt.h"

namespace curvebench::cli {
namespace {

struct Hunt_command_options {
  bench::Hunt_options hunt;
  bool json = false;
};

void run_hunt(const Hunt_command_options& o) {
  const bench::Hunt_summary summary = bench::hunt(o.hunt);
  if (o.json) {
    std::cout << bench::hunt_summary_json(summary, o.hunt) << '\n';
    return;
  }
  std::cout << "hunt " << o.hunt.algorithm << ": " << summary.cases << " cases in " << summary.seconds << " s, "
            << summary.findings.size() << (summary.findings.size() == 1 ? " finding" : " findings") << '\n';
  for (const bench::Hunt_finding& f : summary.findings) {
    std::cout << "  " << f.kind << " on " << f.points.size() << " points (shrunk in " << f.shrink_steps
              << " steps): " << f.message << '\n';
    if (!f.directory.empty()) std::cout << "    replay: " << (f.directory / "replay.sh").string() << '\n';
  }
}

}  // namespace

void add_hunt_command(CLI::App& app) {
  auto o = std::make_shared<Hunt_command_options>();
  CLI::App* command = app.add_subcommand(
      "hunt", "Search an algorithm (built-in or exec:) for crashes, hangs, invalid output and broken laws, shrunk");
  command->add_option("-a,--algorithm", o->hunt.algorithm, "Algorithm name, exec:COMMAND or a name from --algorithm-file")
      ->required();
  add_algorithm_file_option(command);
  command->add_option("--seconds", o->hunt.seconds, "Search time; shrinking a finding may add up to as much again")
      ->capture_default_str();
  command->add_option("--seed", o->hunt.seed, "Seed of the generated inputs")->capture_default_str();
  command->add_option("--timeout", o->hunt.case_timeout, "Seconds per run of the algorithm before it counts as a hang")
      ->capture_default_str();
  command->add_option("--stop-after", o->hunt.stop_after, "Stop after this many findings (0: search all the time)");
  command->add_option("-o,--output", o->hunt.output, "Write each finding to DIR/KIND-N/ (points.xy, replay.sh)");
  command->add_flag("--json", o->json, "Print the summary as JSON");
  command->callback([o] { run_hunt(*o); });
}

}  // namespace curvebench::cli
