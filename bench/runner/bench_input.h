// The input of a benchmark job, named by a string that makes it again, bit for bit, on any
// machine: a source and its sampling and perturbation settings (survey, "Sampling Tools",
// "Robustness to Noise", "Outliers").
//
//   SOURCE|KEY=VALUE|KEY=VALUE...
//
// SOURCE is a curve spec (geometry/curves/curve_spec.h: `svg:data/svg/simple.svg`, `glyph:g`,
// `corner:angle=30`, `fourier:seed=3`, ...) or `file:PATH`, a point file without ground
// truth. A curve takes exactly one sampler key:
//   epsilon=E     safe epsilon-sampling: measured epsilon <= E (geometry/sampling/sampling.h)
//   walk=E        the survey's greedy walk at E (measures about E / 2 on smooth curves)
//   rho=R         HNN-Crust's rho-sampling, safe: measured rho <= R (safe_rho_sampling)
//   uniform=N     N points at equal arc-length steps
//   per-circle=N  equal arc-length steps of 2 pi / N: N points per unit circle (the
//                 survey's sharp-corner family; the first sample is the corner)
// and optionally
//   uniformity=U  with epsilon=: graded until every point's longer / shorter chord is
//                 below U (Connect2D's local uniformity; graded_epsilon_sampling)
//   crossings=1   a sample at every crossing, shared by both branches (degree 4 in the
//                 ground truth; geometry/sampling/sampling.h, with_crossing_samples)
// and any of these perturbations, applied in this order (a file takes noise and outliers):
//   noise=D       uniform noise of extent D x bounding-box diagonal
//   lfs-noise=D   noise along the normal, uniform in [-D, D] x lfs
//   outliers=P    P percent outliers in the bounding box
//   seed=S        seed of every random choice (default 0; noise, lfs noise and outliers
//                 draw from S + 1, S + 2, S + 3, as `curvebench sample` does)
// Relative paths are read from the working directory, else from the source tree.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/metrics/curve_distance.h"
#include "geometry/edge.h"
#include "geometry/kernel.h"
#include "geometry/lfs/local_feature_size.h"

namespace curvebench::bench {

using geometry::Edge;
using geometry::Point;

// The original curve as a dense polyline (within 1e-4 of its bounding-box diagonal): what
// distances are measured against.
struct Polyline {
  std::vector<Point> points;  // its vertices
  std::vector<Edge> edges;    // between `points`
  // Both as a view, valid while this Polyline lives unchanged.
  geometry::Polyline_view view() const { return {points, edges}; }
};

// One input, made from its name: its points and, for a curve, what they are measured against.
struct Bench_input {
  std::string name;          // the name it was made from
  std::vector<Point> points;  // the points an algorithm gets, perturbations applied
  std::optional<std::vector<Edge>> truth;  // canonical, over `points`; none for a point file
  std::shared_ptr<const Polyline> curve;   // null for a point file
  // The sampling's measured epsilon and rho (certify/sampling_measure.h, true lfs, no
  // floor: infinite near a sharp point) and its local uniformity over the ground truth,
  // for a curve sample without noise or outliers.
  std::optional<double> epsilon = {}, rho = {}, uniformity = {};  // local uniformity (see epsilon)
  // \var rho
  // The measured rho (see epsilon).
};

// Inputs named `names`, all of one source (the part before the first '|'), which is read
// and, for a curve, analysed (lfs) once. Throws std::invalid_argument naming the input for
// a malformed name, and passes on the errors of the curve sources and point files.
std::vector<Bench_input> make_bench_inputs(std::span<const std::string> names);

// The curve of `lfs` as a dense polyline, as Bench_input::curve holds it.
Polyline dense_polyline(const geometry::Local_feature_size& lfs);

// The source of an input name: its part before the first '|'.
std::string_view input_source(std::string_view name);

// `path` as given if it exists, else below resource_root() (where data/ is).
std::filesystem::path resolve_data_path(const std::filesystem::path& path);

}  // namespace curvebench::bench
