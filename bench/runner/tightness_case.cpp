#include "bench/runner/tightness_case.h"

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include <nlohmann/json.hpp>

#include "bench/runner/external_algorithm.h"
#include "geometry/io/edge_io.h"
#include "geometry/io/point_io.h"
#include "geometry/io/svg_picture.h"

namespace curvebench::bench {
namespace {

// The case's files; returns its directory's JSON record.
nlohmann::json write_case(const std::filesystem::path& directory, const algorithms::Algorithm& algorithm,
                          const certify::Tightness_result& result) {
  const certify::Tightness_case& c = *result.best;
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  geometry::write_points(directory / "points.xy", c.sample.points);
  geometry::write_edges(directory / "truth.edges", geometry::canonical_edges(c.sample.edges));
  geometry::write_edges(directory / "reconstruction.edges", c.reconstruction);
  std::ofstream(directory / "curve.txt") << c.curve << '\n';

  geometry::SvgPicture picture(c.sample.points);
  const std::string measure(certify::measure_name(result.theorem.measure));
  std::ostringstream title;
  title << algorithm.name << " fails at measured " << measure << ' ' << std::setprecision(4) << c.measured
        << " (proven bound " << result.theorem.bound << "): " << c.curve;
  picture.set_title(title.str());
  picture.add_edges(c.sample.edges, {.colour = "#bbbbbb", .width_px = 5, .legend = "ground truth"});
  picture.add_edges(c.reconstruction, {.colour = "#d62728", .width_px = 1.5, .legend = std::string(algorithm.name)});
  picture.add_points();
  picture.write(directory / "picture.svg");

  std::ofstream replay(directory / "replay.sh");
  replay << "#!/bin/sh\n# " << algorithm.name << " does not reconstruct these " << c.sample.size()
         << " points of " << c.curve << "\n# (measured " << measure << ' ' << std::setprecision(17) << c.measured
         << "; proven bound " << result.theorem.bound << "). Run from this directory with curvebench on PATH.\n"
         << "set -e\ncurvebench reconstruct " << replay_arguments(algorithm)
         << " -i points.xy -o replayed.edges --svg replayed.svg\n"
         << "cmp replayed.edges reconstruction.edges && echo 'the same edges as found'\n"
         << "curvebench evaluate -i points.xy -e replayed.edges -g truth.edges\n"
         << "curvebench measure --curve " << shell_quoted(c.curve) << " -i points.xy -e truth.edges --min-lfs 0\n";
  replay.close();
  std::filesystem::permissions(directory / "replay.sh", std::filesystem::perms::owner_exec, std::filesystem::perm_options::add);

  const nlohmann::json record = {{"algorithm", algorithm.name},  {"measure", measure},
                                 {"bound", result.theorem.bound}, {"smallest_failure", c.measured},
                                 {"ratio", c.measured / result.theorem.bound},
                                 {"curve", c.curve},              {"points", c.sample.size()},
                                 {"level", c.level},              {"samples_added", c.added},
                                 {"moves_kept", c.moved},         {"error", c.error},
                                 {"largest_passed", result.largest_passed},
                                 {"curves", result.curves},       {"failing_curves", result.failing_curves},
                                 {"evaluations", result.evaluations}, {"seconds", result.seconds},
                                 {"directory", directory.string()}};
  std::ofstream(directory / "case.json") << record.dump(2) << '\n';
  return record;
}

}  // namespace

std::string tightness_record_json(const algorithms::Algorithm& algorithm, const certify::Tightness_result& result,
                                  const std::filesystem::path& directory) {
  if (result.best) return write_case(directory, algorithm, result).dump(2);
  const nlohmann::json record = {{"algorithm", algorithm.name},     {"bound", result.theorem.bound},
                                 {"largest_passed", result.largest_passed},
                                 {"curves", result.curves},         {"failing_curves", result.failing_curves},
                                 {"evaluations", result.evaluations}, {"seconds", result.seconds}};
  return record.dump(2);
}

}  // namespace curvebench::bench
