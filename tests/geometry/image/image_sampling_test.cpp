#include "geometry/image/image_sampling.h"

#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>
#include <numbers>
#include <numeric>
#include <set>

#include <CGAL/Exact_rational.h>

#include "geometry/curves/analytic_curves.h"

namespace curvebench::geometry {
namespace {

// ---- oracles, from the definitions ---------------------------------------------------

bool object(const Binary_image& image, long long x, long long y) {
  return x >= 0 && y >= 0 && x < static_cast<long long>(image.width) && y < static_cast<long long>(image.height) &&
         image.pixels[static_cast<std::size_t>(y) * image.width + static_cast<std::size_t>(x)] != 0;
}

std::set<Pixel> brute_force_boundary(const Binary_image& image) {
  std::set<Pixel> found;
  for (int y = 0; y < static_cast<int>(image.height); ++y)
    for (int x = 0; x < static_cast<int>(image.width); ++x)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          if (object(image, x, y) && !object(image, x + dx, y + dy)) found.emplace(x, y);
  return found;
}

long long squared_distance(const Pixel& p, const Pixel& q) {
  const long long dx = p.first - q.first, dy = p.second - q.second;
  return dx * dx + dy * dy;
}

// n < radius², in exact rational arithmetic (independent of erasure_threshold's fma).
bool closer_than(long long n, double radius) {
  const CGAL::Exact_rational r(radius);
  return CGAL::Exact_rational(static_cast<long>(n)) < r * r;
}

std::vector<std::uint64_t> bits(const Sample& sample) {
  std::vector<std::uint64_t> all;
  for (const Point& p : sample.points) all.insert(all.end(), {std::bit_cast<std::uint64_t>(p.x()), std::bit_cast<std::uint64_t>(p.y())});
  return all;
}

// The laws of the survey's erasure and of our ground truth, each against an oracle;
// returns a description of the first broken law, or "" if none is.
std::string broken_law(const Binary_image& image, double radius, const Image_sample& result) {
  const std::set<Pixel> boundary = brute_force_boundary(image);
  const Sample& sample = result.sample;
  const std::size_t n = sample.size();
  if (result.pixels.size() != n || sample.lfs.size() != n || sample.locations.size() != n || sample.labels.size() != n)
    return "per-point data of the wrong size";
  for (std::size_t i = 0; i < n; ++i) {
    if (!boundary.contains(result.pixels[i])) return "a sample is not a boundary pixel";
    const auto [x, y] = result.pixels[i];
    if (sample.points[i] != Point(x + 0.5, static_cast<double>(image.height) - y - 0.5)) return "a point is not its pixel's centre";
    for (std::size_t j = 0; j < i; ++j)
      if (closer_than(squared_distance(result.pixels[i], result.pixels[j]), radius)) return "two samples closer than r";
  }
  for (const Pixel& p : boundary)
    if (std::none_of(result.pixels.begin(), result.pixels.end(), [&](const Pixel& s) { return closer_than(squared_distance(p, s), radius); }))
      return "a boundary pixel is not erased by any sample";
  if (boundary.empty() != (n == 0)) return "samples without boundary or boundary without samples";
  // Ground truth: consecutive blocks of points, one per loop, each a cycle, edge or point.
  std::vector<Edge> expected;
  std::size_t first = 0;
  for (const std::size_t count : result.loop_sizes) {
    if (count == 0) return "an empty loop is listed";
    for (std::size_t i = first; i + 1 < first + count; ++i) expected.emplace_back(i, i + 1);
    if (count >= 3) expected.emplace_back(first + count - 1, first);
    first += count;
  }
  if (first != n) return "the loops do not hold every sample once";
  if (sample.edges != expected) return "the ground truth is not a chain per loop";
  return "";
}

// The contour laws: every loop pixel a boundary pixel, consecutive ones distinct
// 8-neighbours (cyclically), every boundary pixel on some loop.
std::string broken_contour_law(const Binary_image& image, const std::vector<std::vector<Pixel>>& loops) {
  const std::set<Pixel> boundary = brute_force_boundary(image);
  std::set<Pixel> on_loops;
  for (const auto& loop : loops) {
    if (loop.empty()) return "an empty loop";
    for (std::size_t k = 0; k < loop.size(); ++k) {
      if (!boundary.contains(loop[k])) return "a loop passes a pixel that is not a boundary pixel";
      on_loops.insert(loop[k]);
      const long long d = squared_distance(loop[k], loop[(k + 1) % loop.size()]);
      if (loop.size() > 1 && (d == 0 || d > 2)) return "consecutive loop pixels are not distinct 8-neighbours";
    }
  }
  if (on_loops != boundary) return "a boundary pixel is on no loop";
  return "";
}

Binary_image from_rows(const std::vector<std::string>& rows) {
  Binary_image image{rows.empty() ? 0 : rows[0].size(), rows.size(), {}};
  for (const auto& row : rows)
    for (const char c : row) image.pixels.push_back(c == '#');
  return image;
}

Binary_image disk(std::size_t size, double r) {
  Binary_image image{size, size, std::vector<std::uint8_t>(size * size, 0)};
  const double c = size / 2.0;
  for (std::size_t y = 0; y < size; ++y)
    for (std::size_t x = 0; x < size; ++x) image.pixels[y * size + x] = std::hypot(x + 0.5 - c, y + 0.5 - c) < r;
  return image;
}

// ---- boundary pixels and loops ---------------------------------------------------------

TEST(BoundaryPixels, AreTheObjectPixelsWithABackgroundPixelAmongTheir8Neighbours) {
  const Binary_image image = from_rows({
      "#######",
      "#######",
      "#######",
      "###.###",
      "#######",
      "#######",
      "#######",
  });
  const std::vector<Pixel> found = boundary_pixels(image);
  EXPECT_EQ(found.size(), 24u + 8u);  // the image's border (outside counts as background), the hole's ring
  EXPECT_TRUE(std::is_sorted(found.begin(), found.end(), [](const Pixel& p, const Pixel& q) {
    return std::pair(p.second, p.first) < std::pair(q.second, q.first);
  }));
  EXPECT_TRUE(std::ranges::count(found, Pixel(2, 2)));  // a diagonal neighbour is enough
  EXPECT_FALSE(std::ranges::count(found, Pixel(1, 1)));
  EXPECT_THROW(boundary_pixels(Binary_image{3, 3, {1, 0}}), std::invalid_argument);
}

TEST(BoundaryPixels, AgreeWithTheDefinitionOnRandomImages) {
  EXPECT_TRUE(rc::check("random binary images", [] {
    const std::size_t width = *rc::gen::inRange<std::size_t>(0, 20), height = *rc::gen::inRange<std::size_t>(0, 20);
    const int percent = *rc::gen::inRange(0, 101);
    Binary_image image{width, height, {}};
    for (std::size_t i = 0; i < width * height; ++i) image.pixels.push_back(*rc::gen::inRange(0, 100) < percent);
    const std::vector<Pixel> found = boundary_pixels(image);
    const std::set<Pixel> expected = brute_force_boundary(image);
    RC_ASSERT(std::set<Pixel>(found.begin(), found.end()) == expected);
    RC_ASSERT(found.size() == expected.size());
  }));
}

TEST(BoundaryContours, ADiskHasOneLoopThroughAllItsBoundaryPixels) {
  const Binary_image image = disk(40, 15);
  const auto loops = boundary_contours(image);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(broken_contour_law(image, loops), "");
  // A simple closed curve of pixels: each boundary pixel passed once.
  EXPECT_EQ(loops[0].size(), boundary_pixels(image).size());
}

TEST(BoundaryContours, DiagonalNeighboursShareOneLoopAndHolesGetTheirOwn) {
  // Two pixels touching at a corner: one object (8-connected), one loop.
  const Binary_image diagonal = from_rows({"#.", ".#"});
  auto loops = boundary_contours(diagonal);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0], (std::vector<Pixel>{{0, 0}, {1, 1}}));
  // A ring: the outer loop and the hole's.
  const Binary_image ring = from_rows({"#####", "#####", "##.##", "#####", "#####"});
  loops = boundary_contours(ring);
  ASSERT_EQ(loops.size(), 2u);
  EXPECT_EQ(loops[0].size(), 16u);
  EXPECT_EQ(loops[1].size(), 8u);  // around the hole: its 4 edge- and 4 corner-neighbours
  EXPECT_EQ(broken_contour_law(ring, loops), "");
  // A single pixel, a line one pixel wide (each pixel passed from both sides), nothing.
  EXPECT_EQ(boundary_contours(from_rows({"...", ".#.", "..."})), (std::vector<std::vector<Pixel>>{{{1, 1}}}));
  loops = boundary_contours(from_rows({"####"}));
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0], (std::vector<Pixel>{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {2, 0}, {1, 0}}));
  EXPECT_TRUE(boundary_contours(Binary_image{0, 0, {}}).empty());
  EXPECT_TRUE(boundary_contours(Binary_image{3, 2, std::vector<std::uint8_t>(6, 0)}).empty());
}

TEST(BoundaryContours, CoverEveryBoundaryPixelOfRandomImages) {
  EXPECT_TRUE(rc::check("random binary images", [] {
    const std::size_t width = *rc::gen::inRange<std::size_t>(0, 20), height = *rc::gen::inRange<std::size_t>(0, 20);
    const int percent = *rc::gen::inRange(0, 101);
    Binary_image image{width, height, {}};
    for (std::size_t i = 0; i < width * height; ++i) image.pixels.push_back(*rc::gen::inRange(0, 100) < percent);
    const auto loops = boundary_contours(image);
    const std::string broken = broken_contour_law(image, loops);
    RC_ASSERT(broken == "");
  }));
}

// ---- the erasure threshold ------------------------------------------------------------

TEST(ErasureThreshold, IsTheCeilingOfTheExactSquare) {
  std::vector<double> radii{0x1p-1074, 0.5, 1, std::nextafter(1.0, 2.0), std::sqrt(2.0), 1.5, 2, 2.5, 3, 1e4, 0x1p26 + 0.5, 0x1p29};
  for (long long k = 1; k < 3000; ++k) {  // squares of integers and the doubles around their roots
    const double root = std::sqrt(static_cast<double>(k));
    radii.insert(radii.end(), {root, std::nextafter(root, 0.0), std::nextafter(root, 1e9)});
  }
  for (const double big : {0x1p27 + 3, 0x1p28 - 1, 4.0e8 + 0.25}) radii.insert(radii.end(), {big, std::nextafter(big, 0.0), std::nextafter(big, 1e18)});
  for (const double r : radii) {
    const std::uint64_t t = erasure_threshold(r);
    const long long below = static_cast<long long>(t) - 1;
    EXPECT_TRUE(closer_than(below, r)) << std::hexfloat << r;  // t - 1 < r²
    EXPECT_FALSE(closer_than(static_cast<long long>(t), r)) << std::hexfloat << r;  // t >= r²
  }
  EXPECT_EQ(erasure_threshold(1e300), erasure_threshold(0x1p29));
  EXPECT_EQ(erasure_threshold(INFINITY), std::uint64_t{1} << 58);
  EXPECT_THROW(erasure_threshold(0), std::invalid_argument);
  EXPECT_THROW(erasure_threshold(-1), std::invalid_argument);
  EXPECT_THROW(erasure_threshold(NAN), std::invalid_argument);
}

// ---- the survey's erasure and the ground truth --------------------------------------------

double random_radius() {
  return *rc::gen::oneOf(rc::gen::map(rc::gen::inRange(1, 4000), [](int k) { return k / 400.0; }),
                         rc::gen::map(rc::gen::inRange(1, 60), [](int k) { return std::sqrt(static_cast<double>(k)); }),
                         rc::gen::element(1.0, std::nextafter(1.0, 2.0), std::sqrt(2.0), 2.0, 1e9));
}

TEST(SampleImageBoundary, KeepsTheSurveysLawsOnRandomImages) {
  EXPECT_TRUE(rc::check("samples are boundary pixels, pairwise >= r apart, and erase every boundary pixel", [] {
    const std::size_t width = *rc::gen::inRange<std::size_t>(0, 24), height = *rc::gen::inRange<std::size_t>(0, 24);
    const int percent = *rc::gen::inRange(0, 101);
    Binary_image image{width, height, {}};
    for (std::size_t i = 0; i < width * height; ++i) image.pixels.push_back(*rc::gen::inRange(0, 100) < percent);
    const double radius = random_radius();
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const Image_sample result = sample_image_boundary(image, radius, seed);
    RC_ASSERT(broken_law(image, radius, result) == "");
    RC_ASSERT(bits(sample_image_boundary(image, radius, seed).sample) == bits(result.sample));
  }));
}

TEST(SampleImageBoundary, OfDegenerateImagesKeepsTheLaws) {
  const std::vector<Binary_image> images{
      Binary_image{0, 0, {}},
      Binary_image{5, 0, {}},
      Binary_image{4, 3, std::vector<std::uint8_t>(12, 0)},
      Binary_image{7, 5, std::vector<std::uint8_t>(35, 1)},  // all object: the border is the boundary
      Binary_image{1, 1, {1}},
      from_rows({".....", "..#..", "....."}),
      from_rows({"#########"}),
      from_rows({"#", "#", "#", "#"}),
      from_rows({"#....", ".#...", "..#..", "...#.", "....#"}),  // a diagonal line
      from_rows({"#.#.#", ".#.#.", "#.#.#"}),                    // a checkerboard
  };
  for (std::size_t i = 0; i < images.size(); ++i)
    for (const double radius : {0.5, 1.0, 1.5, 2.0, 3.7, 100.0}) {
      SCOPED_TRACE(std::to_string(i) + ", r = " + std::to_string(radius));
      const Image_sample result = sample_image_boundary(images[i], radius, 7);
      EXPECT_EQ(broken_law(images[i], radius, result), "");
    }
  EXPECT_EQ(sample_image_boundary(Binary_image{7, 5, std::vector<std::uint8_t>(35, 1)}, 1, 3).sample.size(), 20u);
  EXPECT_EQ(sample_image_boundary(Binary_image{7, 5, std::vector<std::uint8_t>(35, 1)}, 100, 3).sample.size(), 1u);
  EXPECT_THROW(sample_image_boundary(Binary_image{1, 1, {1}}, 0, 1), std::invalid_argument);
  EXPECT_THROW(sample_image_boundary(Binary_image{1, 1, {1}}, NAN, 1), std::invalid_argument);
}

TEST(SampleImageBoundary, OfALongColumnKeepsTheLaws) {
  EXPECT_TRUE(sample_image_boundary(Binary_image{0, std::size_t{1} << 28, {}}, 2, 1).sample.points.empty());
  // A column one pixel wide and 2^18 high: every pixel is a boundary pixel; the samples
  // are at least 3 apart and leave no gap of 5 (whose middle pixel would be 3 from both).
  const std::size_t height = std::size_t{1} << 18;
  const Image_sample result = sample_image_boundary(Binary_image{1, height, std::vector<std::uint8_t>(height, 1)}, 3, 1);
  std::vector<int> rows;
  for (const auto& [x, y] : result.pixels) rows.push_back(y);
  std::sort(rows.begin(), rows.end());
  ASSERT_FALSE(rows.empty());
  EXPECT_LE(rows.front(), 2);
  EXPECT_GE(rows.back(), static_cast<int>(height) - 3);
  for (std::size_t i = 1; i < rows.size(); ++i) {
    EXPECT_GE(rows[i] - rows[i - 1], 3);
    EXPECT_LE(rows[i] - rows[i - 1], 5);
  }
  ASSERT_EQ(result.loop_sizes.size(), 1u);
  EXPECT_EQ(result.sample.edges.size(), result.sample.size());
}

TEST(SampleImageBoundary, IsReproducibleAndDependsOnTheSeed) {
  const Binary_image image = disk(120, 50);
  const Image_sample a = sample_image_boundary(image, 4, 11);
  EXPECT_EQ(bits(a.sample), bits(sample_image_boundary(image, 4, 11).sample));
  EXPECT_EQ(a.sample.edges, sample_image_boundary(image, 4, 11).sample.edges);
  EXPECT_NE(bits(a.sample), bits(sample_image_boundary(image, 4, 12).sample));
}

// The ground truth as a graph: the degree of every point and the number of cycles.
std::pair<std::map<std::size_t, int>, std::size_t> degrees_and_cycles(const Sample& sample) {
  std::map<std::size_t, int> degree;
  for (const auto& [i, j] : sample.edges) ++degree[i], ++degree[j];
  std::size_t cycles = 0;  // components of a graph whose degrees are all 2
  std::vector<std::size_t> parent(sample.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const auto root = [&](std::size_t i) { while (parent[i] != i) i = parent[i] = parent[parent[i]]; return i; };
  for (const auto& [i, j] : sample.edges) parent[root(i)] = root(j);
  for (std::size_t i = 0; i < sample.size(); ++i) cycles += root(i) == i;
  return {degree, cycles};
}

TEST(SampleImageBoundary, OfADiskIsOneCycleOfShortEdges) {
  for (const double radius : {3.0, 6.5}) {
    const Image_sample result = sample_image_boundary(disk(100, 40), radius, 5);
    const Sample& sample = result.sample;
    ASSERT_GE(sample.size(), 10u);
    EXPECT_EQ(broken_law(disk(100, 40), radius, result), "");
    const auto [degree, cycles] = degrees_and_cycles(sample);
    EXPECT_EQ(cycles, 1u);
    EXPECT_EQ(sample.edges.size(), sample.size());
    for (std::size_t i = 0; i < sample.size(); ++i) EXPECT_EQ(degree.at(i), 2);
    // Neighbours along the boundary: no gap wider than the two erasure discs.
    for (const auto& [i, j] : sample.edges) EXPECT_LT(std::sqrt(CGAL::squared_distance(sample.points[i], sample.points[j])), 2 * radius + 2);
  }
}

TEST(SampleImageBoundary, OfARectangleIsOneCycle) {
  Binary_image image{30, 20, std::vector<std::uint8_t>(600, 0)};
  for (std::size_t y = 3; y < 17; ++y)
    for (std::size_t x = 5; x < 25; ++x) image.pixels[y * 30 + x] = 1;
  const Image_sample result = sample_image_boundary(image, 2.5, 1);
  EXPECT_EQ(broken_law(image, 2.5, result), "");
  const auto [degree, cycles] = degrees_and_cycles(result.sample);
  EXPECT_EQ(cycles, 1u);
  for (std::size_t i = 0; i < result.sample.size(); ++i) EXPECT_EQ(degree.at(i), 2);
}

TEST(SampleImageBoundary, OfAnAnnulusIsTwoCycles) {
  Binary_image image = disk(100, 45);
  const Binary_image hole = disk(100, 20);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] &= !hole.pixels[i];
  const Image_sample result = sample_image_boundary(image, 3, 9);
  EXPECT_EQ(broken_law(image, 3, result), "");
  ASSERT_EQ(result.loop_sizes.size(), 2u);
  const auto [degree, cycles] = degrees_and_cycles(result.sample);
  EXPECT_EQ(cycles, 2u);
  for (std::size_t i = 0; i < result.sample.size(); ++i) {
    EXPECT_EQ(degree.at(i), 2);
    // The first loop is the outer one (it starts at the topmost pixel), then the hole's.
    const double r = std::hypot(result.sample.points[i].x() - 50, result.sample.points[i].y() - 50);
    EXPECT_NEAR(r, i < result.loop_sizes[0] ? 44.5 : 20.5, 1.5);
  }
}

TEST(SampleImageBoundary, MapsARasterizedCurveBackToItsCoordinates) {
  Raster_frame frame;
  const Binary_image image = rasterize(circle(3), 200, &frame);
  const Image_sample result = sample_image_boundary(image, 5, 2, &frame);
  const double pixel = 1 / frame.scale;
  ASSERT_GT(result.sample.size(), 20u);
  for (std::size_t i = 0; i < result.sample.size(); ++i) {
    const Point& p = result.sample.points[i];
    EXPECT_NEAR(std::hypot(p.x(), p.y()), 3, 1.5 * pixel);  // a background 8-neighbour is outside: within sqrt(2) + 0.05
    const auto [x, y] = result.pixels[i];
    EXPECT_EQ(p, frame.to_curve(x + 0.5, y + 0.5));
  }
  const auto [degree, cycles] = degrees_and_cycles(result.sample);
  EXPECT_EQ(cycles, 1u);
}

}  // namespace
}  // namespace curvebench::geometry
