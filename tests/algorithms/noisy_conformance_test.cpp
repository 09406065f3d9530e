// FitConnect and StretchDenoise against the authors' program (stefango74/fitconnect, built
// unchanged but for a headless driver: their invertY, MODE_BLEND) on the authors' 24 point
// sets (data/stretchdenoise/, bundled). Their program returns a manifold on every file; the
// table below is the shape of its output (components, closed ones, open ends) and its
// coverage, read off that output: the share of input points within 5% of the output's
// bounding-box diagonal of the output curve. Ours must give a manifold of the same shape
// whose coverage is at most 0.08 below theirs. The issue asked for every point within 5%;
// the authors' own program misses that on 6 files (fish.txt 0.790), so their coverage is
// the reference. Where ours differs in shape, the file is listed with the reason, and a
// listed file that comes to match fails, so the list cannot go stale.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "algorithms/registry.h"
#include "geometry/curves/analytic_curves.h"
#include "geometry/io/point_io.h"
#include "geometry/lfs/local_feature_size.h"
#include "geometry/sampling/sampling.h"
#include "geometry/sampling/sampling_noise.h"

namespace curvebench::algorithms {
namespace {

namespace fs = std::filesystem;

struct Authors_shape {
  std::string file;
  std::size_t closed, open;  // components of the authors' output
  double coverage;           // of the input by the authors' output (unblended positions)
};

// One closed curve on 17 files; the vases and the drill case are several closed curves;
// the stairs one open chain.
const std::vector<Authors_shape> kAuthors{
    {"Circle0.txt", 1, 0, 1.000},
    {"Cup0.txt", 1, 0, 0.943},
    {"Keyboard0.txt", 1, 0, 1.000},
    {"Monitor0.txt", 1, 0, 0.960},
    {"Mouse0.txt", 1, 0, 1.000},
    {"apple_2percent_noise.txt", 1, 0, 1.000},
    {"bot.txt", 1, 0, 0.958},
    {"butterfly_2percent_noise.txt", 1, 0, 1.000},
    {"crab_2percent_noise.txt", 1, 0, 0.996},
    {"dolphin_2percent_noise.txt", 1, 0, 1.000},
    {"drill.txt", 1, 0, 1.000},
    {"drill2_xyz.txt", 1, 0, 1.000},
    {"drill_xyz.txt", 1, 0, 0.919},
    {"drillcase_xyz.txt", 6, 0, 1.000},
    {"family.p2d", 1, 0, 1.000},
    {"fish.txt", 1, 0, 0.790},
    {"stair-noise00.xy", 0, 1, 1.000},
    {"stair.xy", 0, 1, 1.000},
    {"stair.xym", 0, 1, 1.000},
    {"thing.txt", 1, 0, 1.000},
    {"vase.txt", 2, 0, 1.000},
    {"vase2_xyz.txt", 2, 0, 1.000},
    {"vase_xyz.txt", 3, 0, 1.000},
    {"what_xyz.txt", 1, 0, 1.000},
};

// Files where ours has another shape than theirs, with the reason.
const std::map<std::string, std::string> kDiffering{
    {"family.p2d",
     "3 closed curves: two 4-point loops (input points 412, 413, 416, 417 and 2890, 2891, 2905, 2906), each a "
     "square of the file's grid, whose four points are cocircular, so that their order along a fit hangs on "
     "the last bits of its centre, which ours and the authors' program round differently; theirs leaves these "
     "points out"},
};

struct Shape {
  std::size_t closed = 0, open = 0, open_ends = 0, isolated = 0, max_degree = 0;
};

// Counted here, without the code under test.
Shape shape_of(std::size_t n, const std::vector<Edge>& edges) {
  std::vector<std::size_t> degree(n, 0), parent(n);
  for (std::size_t v = 0; v < n; ++v) parent[v] = v;
  const auto root = [&](std::size_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const auto& [i, j] : edges) ++degree[i], ++degree[j], parent[root(i)] = root(j);
  std::set<std::size_t> components, open;
  Shape shape;
  for (std::size_t v = 0; v < n; ++v) {
    shape.max_degree = std::max(shape.max_degree, degree[v]);
    if (degree[v] == 0) {
      ++shape.isolated;
      continue;
    }
    components.insert(root(v));
    if (degree[v] != 2) open.insert(root(v));
    shape.open_ends += degree[v] == 1;
  }
  shape.open = open.size();
  shape.closed = components.size() - open.size();
  return shape;
}

double distance_to_segment(const Point& p, const Point& a, const Point& b) {
  const double vx = b.x() - a.x(), vy = b.y() - a.y(), wx = p.x() - a.x(), wy = p.y() - a.y();
  const double length2 = vx * vx + vy * vy;
  const double t = length2 > 0 ? std::clamp((wx * vx + wy * vy) / length2, 0.0, 1.0) : 0.0;
  return std::hypot(wx - t * vx, wy - t * vy);
}

// The share of input points within `within` times the output curve's bounding-box
// diagonal of the output curve.
double coverage(double within, const std::vector<Point>& input, const Reconstruction& output) {
  double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
  for (const Point& p : output.points)
    xmin = std::min(xmin, p.x()), xmax = std::max(xmax, p.x()), ymin = std::min(ymin, p.y()), ymax = std::max(ymax, p.y());
  const double limit = within * std::hypot(xmax - xmin, ymax - ymin);
  std::size_t covered = 0;
  for (const Point& p : input) {
    double nearest = INFINITY;
    for (const auto& [i, j] : output.edges) nearest = std::min(nearest, distance_to_segment(p, output.points[i], output.points[j]));
    covered += nearest <= limit;
  }
  return static_cast<double>(covered) / static_cast<double>(input.size());
}

void expect_authors_shapes(const std::string& algorithm) {
  const fs::path folder = fs::path(CURVEBENCH_SOURCE_DIR) / "data" / "stretchdenoise";
  std::size_t matching = 0;
  for (const Authors_shape& authors : kAuthors) {
    SCOPED_TRACE(algorithm + " on " + authors.file);
    const std::vector<Point> input = geometry::read_point_file(folder / authors.file).points;
    const Reconstruction output = reconstruct(*find_algorithm(algorithm), input);
    ASSERT_FALSE(output.points.empty());
    const Shape ours = shape_of(output.points.size(), output.edges);
    EXPECT_LE(ours.max_degree, 2u) << "not a manifold";
    EXPECT_EQ(ours.isolated, 0u) << "an output point on no curve";
    EXPECT_EQ(ours.open_ends, 2 * ours.open) << "not a manifold";
    const double covered = coverage(0.05, input, output);
    std::cout << algorithm << " " << authors.file << ": " << output.points.size() << " points, coverage "
              << covered << '\n';
    EXPECT_GE(covered, authors.coverage - 0.08) << "input points far from the output curve (the authors' "
                                                   << "program covers " << authors.coverage << ")";
    const bool same = ours.closed == authors.closed && ours.open == authors.open;
    matching += same;
    if (const auto listed = kDiffering.find(authors.file); listed != kDiffering.end())
      EXPECT_FALSE(same) << "now shaped as the authors' output (listed as: " << listed->second
                         << "): take it off the list";
    else
      EXPECT_TRUE(same) << ours.closed << " closed and " << ours.open << " open components; the authors' program: "
                        << authors.closed << " and " << authors.open;
  }
  EXPECT_EQ(matching, kAuthors.size() - kDiffering.size());
}

TEST(NoisyConformance, FitConnectHasTheAuthorsShapeOnTheirData) { expect_authors_shapes("fit-connect"); }

TEST(NoisyConformance, StretchDenoiseHasTheAuthorsShapeOnTheirData) { expect_authors_shapes("stretch-denoise"); }

// The flagship noisy input: a band of 1000 points thins to a few dozen representatives.
TEST(NoisyConformance, FishThinsToFewRepresentatives) {
  const std::vector<Point> input =
      geometry::read_point_file(fs::path(CURVEBENCH_SOURCE_DIR) / "data/stretchdenoise/fish.txt").points;
  for (const std::string algorithm : {"fit-connect", "stretch-denoise"}) {
    const Reconstruction output = reconstruct(*find_algorithm(algorithm), input);
    EXPECT_GE(output.points.size(), 20u) << algorithm;
    EXPECT_LE(output.points.size(), 60u) << algorithm << " (the authors' program keeps 41)";
    EXPECT_EQ(output.edges.size(), output.points.size()) << algorithm << ": one closed curve";
  }
}

// The survey's noise models at their heaviest levels in the benchmark (lfs noise delta 0.5,
// uniform noise 3% of the diagonal) on 20 smooth closed curves at epsilon 0.3: one closed
// curve on at least 19 (the benchmark's noisy and lfsnoise suites measure the rate on 30
// curves per level, with intervals).
TEST(NoisyConformance, OneClosedCurveOnSmoothCurvesWithHeavyNoise) {
  for (const std::string algorithm : {"fit-connect", "stretch-denoise"})
    for (const bool lfs_noise : {true, false}) {
      int closed = 0;
      for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        const geometry::Local_feature_size lfs(geometry::random_fourier_curve(seed));
        const geometry::Sample clean = geometry::safe_epsilon_sampling(lfs, 0.3, geometry::default_minimum_lfs(lfs));
        const geometry::Sample noisy =
            lfs_noise ? geometry::with_lfs_noise(lfs, clean, 0.5, seed) : geometry::with_uniform_noise(clean, 0.03, seed);
        const Reconstruction output = reconstruct(*find_algorithm(algorithm), noisy.points);
        const Shape shape = shape_of(output.points.size(), output.edges);
        closed += shape.closed == 1 && shape.open == 0 && shape.isolated == 0 && shape.max_degree == 2;
      }
      std::cout << algorithm << (lfs_noise ? ", lfs noise 0.5: " : ", uniform noise 0.03: ") << closed
                << " of 20 one closed curve\n";
      EXPECT_GE(closed, 19) << algorithm << (lfs_noise ? " lfs noise" : " uniform noise");
    }
}

}  // namespace
}  // namespace curvebench::algorithms
