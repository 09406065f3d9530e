#include "bench/cli/list_command.h"

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "algorithms/registry.h"
#include "bench/runner/resources.h"
#include "bench/runner/suite.h"
#include "graphs/proximity_graph.h"

namespace curvebench::cli {
namespace {

struct List_options {
  std::string what = "algorithms";
  bool names_only = false;
};

std::string_view word(algorithms::Support support) {
  switch (support) {
    case algorithms::Support::yes: return "yes";
    case algorithms::Support::only: return "only";
    default: return "no";
  }
}

// The survey's Table 1 row and sampling condition of each algorithm, then its parameters.
void list_algorithms() {
  std::cout << std::left << std::setw(20) << "name" << std::setw(6) << "n.-u." << std::setw(6) << "noise"
            << std::setw(6) << "outl." << std::setw(9) << "manifold" << std::setw(6) << "open" << std::setw(6)
            << "mult." << std::setw(6) << "sharp" << std::setw(6) << "guar." << std::setw(12) << "time"
            << "sampling condition\n";
  for (const algorithms::Algorithm& a : algorithms::registry()) {
    const algorithms::Capabilities& c = a.capabilities;
    std::cout << std::setw(20) << a.name << std::setw(6) << word(c.non_uniform) << std::setw(6) << word(c.noise)
              << std::setw(6) << word(c.outliers) << std::setw(9) << word(c.manifold) << std::setw(6) << word(c.open)
              << std::setw(6) << word(c.multiple) << std::setw(6) << word(c.sharp) << std::setw(6)
              << (c.guarantee ? "yes" : "no") << std::setw(12) << c.time_complexity << a.condition.statement << '\n';
  }
  std::cout << '\n';
  for (const algorithms::Algorithm& a : algorithms::registry()) {
    std::cout << a.name << ": " << a.title << " (" << a.reference << ")\n";
    for (const algorithms::Parameter& p : a.parameters) {
      std::ostringstream range;
      range << p.default_value << " in [" << p.minimum << ", " << p.maximum << ']';
      std::cout << "    " << std::setw(17) << p.name << std::setw(28) << range.str() << p.meaning << '\n';
    }
  }
}

void run_list(const List_options& options) {
  if (options.what == "algorithms") {
    if (options.names_only)
      for (const auto& algorithm : algorithms::registry()) std::cout << algorithm.name << '\n';
    else
      list_algorithms();
    return;
  }
  if (options.what == "data") {  // where the suites' data/... and the report's scripts are read
    const std::filesystem::path root = bench::resource_root();
    std::cout << "data: " << (root / "data").string() << "\nreport: " << (root / "bench/report").string() << '\n';
    return;
  }
  if (options.what == "suites") {
    std::size_t width = 0;
    for (const bench::Suite& suite : bench::suites()) width = std::max(width, suite.name.size() + 2);
    for (const bench::Suite& suite : bench::suites()) {
      if (options.names_only) {
        std::cout << suite.name << '\n';
        continue;
      }
      std::cout << std::left << std::setw(static_cast<int>(width)) << suite.name << suite.description << '\n';
      if (!suite.variable.empty()) {
        std::cout << std::setw(static_cast<int>(width)) << "" << suite.variable << ":";
        for (const std::string_view level : suite.levels) std::cout << ' ' << level;
        std::cout << '\n';
      }
    }
    return;
  }
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
  CLI::App* command = app.add_subcommand("list", "List the reconstruction algorithms, the proximity graphs, the benchmark suites, or where the bundled data is");
  command->add_option("WHAT", options->what, "algorithms, graphs, suites or data")
      ->check(CLI::IsMember({"algorithms", "graphs", "suites", "data"}))
      ->capture_default_str();
  command->add_flag("--names", options->names_only, "One name per line, for scripts");
  command->callback([options] { run_list(*options); });
}

}  // namespace curvebench::cli
