// What `curvebench tightness` keeps of one search (certify/tightness_search.h): the failing
// case of smallest measure as files a person can replay, and the search's record (JSON).
// The command line and the Python module (curvebench.tightness) both write through here.
#pragma once

#include <filesystem>
#include <string>

#include "algorithms/algorithm.h"
#include "certify/tightness_search.h"

namespace curvebench::bench {

// The record of a search of `algorithm` (JSON): algorithm, bound, largest_passed, curves,
// failing_curves, evaluations and seconds. If the search found a failing case, the case is
// first written to `directory` (made anew: points.xy, truth.edges, reconstruction.edges,
// curve.txt, picture.svg, replay.sh and case.json), and the record is case.json's, which
// adds measure, smallest_failure, ratio (to the bound), curve, points, level,
// samples_added, moves_kept, error and directory.
std::string tightness_record_json(const algorithms::Algorithm& algorithm, const certify::Tightness_result& result,
                                  const std::filesystem::path& directory);

}  // namespace curvebench::bench
