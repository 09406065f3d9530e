#include "bench/cli/list_command.h"

#include <iomanip>
#include <iostream>
#include <memory>

#include "graphs/proximity_graph.h"

namespace curvebench::cli {
namespace {

struct List_options {
  std::string what = "graphs";
  bool names_only = false;
};

void run_list(const List_options& options) {
  for (const auto& graph : graphs::proximity_graphs()) {
    if (options.names_only)
      std::cout << graph.name << '\n';
    else
      std::cout << std::left << std::setw(14) << graph.name << graph.description << '\n';
  }
}

}  // namespace

void add_list_command(CLI::App& app) {
  auto options = std::make_shared<List_options>();
  CLI::App* command = app.add_subcommand("list", "List what curvebench can build");
  command->add_option("WHAT", options->what, "graphs")->check(CLI::IsMember({"graphs"}))->capture_default_str();
  command->add_flag("--names", options->names_only, "One name per line, for scripts");
  command->callback([options] { run_list(*options); });
}

}  // namespace curvebench::cli
