#include "bench/cli/algorithm_options.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "algorithms/registry.h"
#include "bench/runner/algorithm_file.h"
#include "bench/runner/external_algorithm.h"

namespace curvebench::cli {

void add_algorithm_file_option(CLI::App* command) {
  command
      ->add_option_function<std::string>(
          "--algorithm-file", [](const std::string& file) { bench::load_algorithm_file(file); },
          "A JSON file of named external algorithms (docs/own-algorithm.md); -a names them")
      ->trigger_on_parse()
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

std::vector<std::string> algorithm_names(const std::vector<std::string>& given) {
  std::vector<std::string> names;
  for (const std::string& item : given) {
    if (item.starts_with(bench::external_prefix)) {
      names.push_back(item);
      continue;
    }
    std::stringstream list(item);
    for (std::string name; std::getline(list, name, ',');)
      if (!name.empty()) names.push_back(name);
  }
  return names;
}

const algorithms::Algorithm& chosen_algorithm(const std::string& given) {
  std::string name = given;
  if (!name.starts_with(bench::external_prefix) && !bench::find_any_algorithm(name)) std::ranges::replace(name, '_', '-');
  const algorithms::Algorithm* algorithm = bench::find_any_algorithm(name);
  if (!algorithm) throw std::invalid_argument("unknown algorithm '" + given + "' (see `curvebench list`)");
  return *algorithm;
}

}  // namespace curvebench::cli
