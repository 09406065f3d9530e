// `curvebench hunt`: a black-box, property-based search for defects of one algorithm,
// built-in or external (exec:), with RapidCheck's generators and shrinking.
//
// Inputs, three of four: small point sets (0 to about 12 points) on an integer lattice, from
// five families: any points, collinear runs, cocircular points, grid points and crowded points
// (duplicates); scaled by a power of two that reaches 2^±1000 and the limits of double, and
// with one coordinate moved by one ulp or none. One of four: a smooth closed curve (one
// Fourier curve, or two for an algorithm that reconstructs several) sampled near and beyond
// the algorithm's epsilon bound (0.5, 0.8 and 0.95 of it, 1.2 and 2 times it; without a
// bound, epsilon 0.6 to 0.1). Defects, each checked
// in a worker process of its own (a crash or a hang costs only its case):
//   crash           the algorithm (or program) was killed by a signal
//   hang            it ran past the case timeout
//   invalid-output  edges out of range, self-loops, unsorted or repeated (built-in), or
//                   what exec: reads as invalid
//   not-deterministic, not-permutation-invariant, not-scale-invariant,
//   not-reflection-invariant
//                   the edges (between input points, duplicates identified) differ between
//                   two runs, or after rotating the input's order by one, doubling every
//                   coordinate or negating every x; the three laws are checked for
//                   algorithms that keep the input points, on input in general
//                   position (no duplicate, three collinear, four cocircular or two equal
//                   distances: there an algorithm breaks ties as it may)
//   not-exact-under-condition
//                   a curve sampling whose measured epsilon (and local uniformity) meets
//                   the algorithm's own bound, certify's hypothesis, reconstructed not
//                   exactly (certify/theorems.h: the same verdict as `curvebench certify`)
// A clear error (an exception, a non-zero exit with a message) is not a defect. Each finding
// is shrunk greedily through RapidCheck's shrinks (fewer points, then smaller coordinates
// and scale; for a sampling: one curve, fewer harmonics, seed 0, the coarsest level) while it
// shows the same defect, and written to DIR/KIND-N/ as points.xy (truth.edges for a
// sampling), the defect's description and replay.sh.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "geometry/kernel.h"

namespace curvebench::bench {

// What `curvebench hunt` searches, for how long, and where it writes what it finds.
struct Hunt_options {
  std::string algorithm = {};    // a registered name or exec:COMMAND
  double seconds = 60;           // search time; shrinking a finding may run on, to 2 seconds + 30 in all
  std::uint64_t seed = 0;        // of the generated cases
  std::filesystem::path output = {};  // findings' directories; empty: none written
  double case_timeout = 10;      // seconds per run of the algorithm
  std::size_t max_findings = 1;  // per defect kind
  std::size_t stop_after = 0;    // stop the search after this many findings; 0: search for `seconds`
};

// A defect found, shrunk.
struct Hunt_finding {
  std::string kind;     // crash, hang, invalid-output, not-...
  std::string message;  // what was seen
  std::vector<geometry::Point> points;  // the shrunk input
  std::size_t shrink_steps = 0;         // shrinks taken that kept the defect
  std::filesystem::path directory;      // where it was written, if it was
  std::string curve = {};               // the sampling's input name (bench_input.h), if it is one
  std::optional<double> epsilon = {};   // its measured epsilon
};

// What a hunt tried and found.
struct Hunt_summary {
  std::size_t cases = 0;  // inputs tried, shrinking not counted
  std::vector<Hunt_finding> findings;  // in the order found, at most max_findings per kind
  double seconds = 0;                  // the hunt's wall time, shrinking included
};

// Throws std::invalid_argument for an unknown algorithm or a bad exec: declaration.
Hunt_summary hunt(const Hunt_options& options);

// The summary as `curvebench hunt --json` prints it: algorithm, seed, cases, seconds and
// findings (each: kind, message, points as [x, y] pairs, shrink_steps, replay: the path of
// its replay.sh, or null when none was written).
std::string hunt_summary_json(const Hunt_summary& summary, const Hunt_options& options);

}  // namespace curvebench::bench
