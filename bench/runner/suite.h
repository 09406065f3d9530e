// The experiments of the benchmark as data (survey, "Benchmark Driver and Test Scripts":
// one test script per experiment, `run-sampling.sh` ...; "Evaluation & Results"). A suite
// names its inputs as templates over one experiment variable: each level of the variable
// substitutes `{}` in every template (followed by the suite's settings), giving input
// names (bench_input.h) that every registered algorithm runs on. A composite suite
// (`default`, `all`) runs other suites.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace curvebench::bench {

// One experiment: input-name templates and the variable whose levels fill them in.
struct Suite {
  std::string_view name;                      // as `curvebench run` takes it
  std::string_view description;               // what it measures, and the survey's section
  // The "= {}" let the table below leave out what a suite does not use, under -Wextra.
  std::vector<std::string_view> inputs = {};  // input-name templates; a source glyph:* stands for every glyph
  std::string_view settings = {};             // appended to every template: "|epsilon={}|lfs-noise=0.1"
  std::string_view variable = {};             // the experiment variable, e.g. "epsilon"; empty: one level
  std::vector<std::string_view> levels = {};  // its values, substituted for {}
  std::vector<std::string_view> parts = {};   // a composite suite: the suites it runs, nothing else
};

// Every suite, in a fixed order (a static table).
std::span<const Suite> suites();
const Suite* find_suite(std::string_view name);  // nullptr if none has that name

// One input of one suite at one level.
struct Suite_case {
  std::string suite;  // the suite (not the composite) the case comes from
  std::string input;  // an input name
  std::string level;  // "variable=value", empty for a suite without levels
};

// The cases of `suite` in a fixed order (a composite's parts in turn, then template by
// template, level by level, glyph by glyph). Throws std::invalid_argument for an unknown
// part.
std::vector<Suite_case> suite_cases(const Suite& suite);

}  // namespace curvebench::bench
