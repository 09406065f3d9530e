// run(), certify(), tightness() and hunt(): the experiments, each as its command runs it,
// with the GIL released while the C++ runs (a Python algorithm takes it back to run).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/registry.h"
#include "bench/runner/certification.h"
#include "bench/runner/external_algorithm.h"
#include "bench/runner/hunt.h"
#include "bench/runner/resources.h"
#include "bench/runner/run.h"
#include "bench/runner/slurm_array.h"
#include "bench/runner/suite.h"
#include "bench/runner/tightness_case.h"
#include "bindings.h"
#include "certify/tightness_search.h"
#include "errors.h"

namespace curvebench::python {
namespace py = pybind11;
namespace {

// The algorithm of that name, or Unknown_name with the command line's message.
const algorithms::Algorithm& named(const std::string& name) {
  const algorithms::Algorithm* algorithm = bench::find_any_algorithm(name);
  if (!algorithm) throw Unknown_name("unknown algorithm '" + name + "' (see `curvebench list`)");
  return *algorithm;
}

bench::Pictures picture_mode(const std::string& name) {
  static const std::map<std::string, bench::Pictures> modes{
      {"some", bench::Pictures::some}, {"all", bench::Pictures::all}, {"failures", bench::Pictures::failures},
      {"none", bench::Pictures::none}};
  const auto found = modes.find(name);
  if (found == modes.end()) throw std::invalid_argument("pictures is some, all, failures or none, not '" + name + "'");
  return found->second;
}

py::dict run(const std::string& suite, const std::vector<std::string>& algorithms, const std::filesystem::path& output,
             std::size_t jobs, double timeout, const std::string& pictures, bool resume, const std::string& shard,
             bool report, bool progress) {
  if (!bench::find_suite(suite)) throw Unknown_name("unknown suite '" + suite + "' (see `curvebench list suites`)");
  for (const std::string& name : algorithms) named(name);
  bench::Run_options options{.suite = suite, .output = output, .algorithms = algorithms, .jobs = jobs};
  std::tie(options.shard, options.shards) = bench::chosen_shard(shard, bench::slurm_array_task_from_environment());
  options.resume = resume;
  options.timeout_seconds = timeout;
  options.pictures = picture_mode(pictures);
  options.report = report;
  options.progress = progress;
  bench::Run_summary s;
  {
    const py::gil_scoped_release released;
    s = bench::run_suite(options);
  }
  py::dict counts;
  counts["jobs"] = s.jobs, counts["resumed"] = s.resumed, counts["ok"] = s.ok, counts["failed"] = s.failed;
  counts["invalid_output"] = s.invalid_output, counts["crashed"] = s.crashed, counts["timeout"] = s.timed_out;
  return counts;
}

std::string certify(const std::string& algorithm, const std::string& curves, std::size_t count, bool rho,
                    std::optional<double> epsilon, std::optional<double> below_bound, std::uint64_t seed,
                    const std::filesystem::path& output, std::size_t jobs, double timeout, bool resume,
                    const std::string& shard, bool progress) {
  const algorithms::Algorithm& chosen = named(algorithm);
  bench::Certify_options o;
  o.curves = curves;
  o.count = count;
  o.measure = rho ? certify::Measure::rho : certify::Measure::epsilon;
  o.level = epsilon;
  if (below_bound) o.below_bound = *below_bound;
  o.seed = seed;
  o.run.output = output;
  o.run.jobs = jobs;
  o.run.timeout_seconds = timeout;
  o.run.resume = resume;
  std::tie(o.run.shard, o.run.shards) = bench::chosen_shard(shard, bench::slurm_array_task_from_environment());
  o.run.progress = progress;
  o.run.pictures = bench::Pictures::failures;  // as `curvebench certify` draws them
  const py::gil_scoped_release released;
  return bench::certify_summary_json(bench::certify_algorithm(chosen, o), o);
}

std::string tightness(const std::string& algorithm, bool rho, double seconds, std::size_t curves, std::size_t moves,
                      std::uint64_t seed, const std::filesystem::path& directory) {
  const algorithms::Algorithm& chosen = named(algorithm);
  certify::Tightness_options o{.measure = rho ? certify::Measure::rho : certify::Measure::epsilon,
                               .seconds = seconds, .seed = seed, .max_curves = curves, .moves = moves};
  const py::gil_scoped_release released;
  return bench::tightness_record_json(chosen, certify::search_tightness(chosen, o), directory);
}

std::string hunt(const std::string& algorithm, double seconds, std::uint64_t seed, const std::filesystem::path& output,
                 double timeout, std::size_t max_findings, std::size_t stop_after) {
  named(algorithm);
  const bench::Hunt_options o{.algorithm = algorithm, .seconds = seconds, .seed = seed, .output = output,
                              .case_timeout = timeout, .max_findings = max_findings, .stop_after = stop_after};
  const py::gil_scoped_release released;
  return bench::hunt_summary_json(bench::hunt(o), o);
}

}  // namespace

void define_experiments(py::module_& m) {
  m.def("run", &run, py::arg("suite"), py::arg("algorithms"), py::arg("output"), py::arg("jobs"), py::arg("timeout"),
        py::arg("pictures"), py::arg("resume"), py::arg("shard"), py::arg("report"), py::arg("progress"),
        "bench::run_suite; the jobs counted by status.");
  m.def("certify", &certify, py::arg("algorithm"), py::arg("curves"), py::arg("count"), py::arg("rho"),
        py::arg("epsilon"), py::arg("below_bound"), py::arg("seed"), py::arg("output"), py::arg("jobs"),
        py::arg("timeout"), py::arg("resume"), py::arg("shard"), py::arg("progress"),
        "bench::certify_algorithm; `curvebench certify --json`'s summary.");
  m.def("tightness", &tightness, py::arg("algorithm"), py::arg("rho"), py::arg("seconds"), py::arg("curves"),
        py::arg("moves"), py::arg("seed"), py::arg("directory"),
        "certify::search_tightness; `curvebench tightness --json`'s record.");
  m.def("hunt", &hunt, py::arg("algorithm"), py::arg("seconds"), py::arg("seed"), py::arg("output"),
        py::arg("timeout"), py::arg("max_findings"), py::arg("stop_after"),
        "bench::hunt; `curvebench hunt --json`'s summary.");
  m.def("suites", [] {
        py::list all;
        for (const bench::Suite& s : bench::suites()) all.append(py::make_tuple(std::string(s.name), std::string(s.description)));
        return all;
      },
      "(name, description) of every suite.");
  m.def("resource_root", [] { return bench::resource_root(); }, "Where the bundled data and report scripts are read.");
  m.def("set_resource_root", [](const std::filesystem::path& root) { bench::set_resource_root(root); },
        py::arg("root"), "Makes `root` the folder of data/ and bench/report/ ($CURVEBENCH_ROOT still wins).");
}

}  // namespace curvebench::python
