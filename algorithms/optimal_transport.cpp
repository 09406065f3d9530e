#include "algorithms/optimal_transport.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

#include <CGAL/Optimal_transportation_reconstruction_2.h>
#include <CGAL/Random.h>
#include <CGAL/bounding_box.h>

#include "geometry/bounding_box_diagonal.h"
#include "geometry/edge.h"

namespace curvebench::algorithms {
namespace {

using Otr = CGAL::Optimal_transportation_reconstruction_2<geometry::Kernel>;

// CGAL's triangulation picks candidate edges with its own generator, seeded from the
// clock (CGAL::Random()), so the same input gave another output a second later. It is a
// public member of the protected triangulation: reseed it here.
class Seeded_otr : public Otr {
 public:
  using Otr::Otr;
  void seed(unsigned int seed) { m_dt.rng = CGAL::Random(seed); }
};

// x -> (x - centre) / 2^e, with 2^e above the half extent, so that every point lands in
// [-1, 1]^2; halved before subtracting and scaled by ldexp so that no step overflows,
// even for points near DBL_MAX, where 2^e itself is not a double.
class Unit_box {
 public:
  explicit Unit_box(std::span<const Point> points) {
    const auto box = CGAL::bounding_box(points.begin(), points.end());
    cx_ = box.xmin() / 2 + box.xmax() / 2;
    cy_ = box.ymin() / 2 + box.ymax() / 2;
    const double half_extent = std::max(box.xmax() / 2 - box.xmin() / 2, box.ymax() / 2 - box.ymin() / 2);
    if (half_extent > 0) std::frexp(half_extent, &exponent_);  // half_extent < 2^exponent_
  }
  Point to_unit(const Point& p) const {
    return {std::ldexp(p.x() / 2 - cx_ / 2, 1 - exponent_), std::ldexp(p.y() / 2 - cy_ / 2, 1 - exponent_)};
  }
  Point from_unit(const Point& q) const {
    return {2 * (cx_ / 2 + std::ldexp(q.x(), exponent_ - 1)), 2 * (cy_ / 2 + std::ldexp(q.y(), exponent_ - 1))};
  }

 private:
  double cx_ = 0, cy_ = 0;
  int exponent_ = 0;
};

}  // namespace

Reconstruction optimal_transport_reconstruction(std::span<const Point> points, const Optimal_transport_options& options) {
  for (const Point& p : points)
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
      throw std::invalid_argument("optimal transport: a point has a non-finite coordinate");
  // CGAL's reconstruction dereferences a missing edge on a single point.
  if (points.size() < 2) return {{}, std::vector<Point>(points.begin(), points.end())};

  const Unit_box unit(points);
  std::vector<Point> unit_points;
  unit_points.reserve(points.size());
  for (const Point& p : points) unit_points.push_back(unit.to_unit(p));
  // Distinct points can meet in the unit box when their coordinates span more than a
  // double's range (5e-324 beside 0, found by `curvebench hunt`); if they all meet, CGAL
  // gets one point, as above.
  if (std::all_of(unit_points.begin(), unit_points.end(), [&](const Point& q) { return q == unit_points.front(); }))
    return {{}, std::vector<Point>(points.begin(), points.end())};

  CGAL::get_default_random() = CGAL::Random(0);
  Seeded_otr otr(unit_points, boost::typed_identity_property_map<Point>(), boost::static_property_map<double>(1),
                 /*sample_size=*/15, /*use_flip=*/true, options.relocation);
  otr.seed(0);
  if (options.vertices > 0)
    otr.run_until(options.vertices);
  else
    otr.run_under_wasserstein_tolerance(options.tolerance * geometry::bounding_box_diagonal(unit_points));

  std::vector<Point> isolated;
  std::vector<geometry::Kernel::Segment_2> segments;
  otr.list_output(std::back_inserter(isolated), std::back_inserter(segments));

  // Vertices numbered in lexicographic order: CGAL lists them in the order of its
  // triangulation's storage, which can differ between runs on the same input.
  Reconstruction result;
  std::map<Point, std::size_t> index;
  for (const auto& segment : segments) index.try_emplace(segment.source(), 0), index.try_emplace(segment.target(), 0);
  for (const Point& q : isolated) index.try_emplace(q, 0);
  for (auto& [q, i] : index) {
    i = result.points.size();
    result.points.push_back(unit.from_unit(q));
  }
  for (const auto& segment : segments) {
    const std::size_t a = index[segment.source()], b = index[segment.target()];
    if (a != b) result.edges.push_back({std::min(a, b), std::max(a, b)});
  }
  result.edges = geometry::canonical_edges(std::move(result.edges));
  return result;
}

Algorithm optimal_transport_algorithm() {
  static const Parameter vertices{.name = "vertices", .type = Parameter_type::integer, .default_value = 0,
                                  .minimum = 0, .maximum = 1e9,
                                  .meaning = "stop at this many output vertices (0: stop at the tolerance)"};
  static const Parameter tolerance{.name = "tolerance", .default_value = Optimal_transport_options{}.tolerance,
                                   .minimum = 0, .maximum = 1,
                                   .meaning = "Wasserstein tolerance as a fraction of the bounding-box diagonal"};
  static const Parameter relocation{.name = "relocation", .type = Parameter_type::integer,
                                    .default_value = Optimal_transport_options{}.relocation, .minimum = 0,
                                    .maximum = 10, .meaning = "vertex relocation steps between two collapses"};
  return {
      .name = "optimal-transport",
      .title = "Optimal Transport",
      .reference = "de Goes, Cohen-Steiner, Alliez, Desbrun 2011",
      .category = "Non-manifold",
      .parameters = {vertices, tolerance, relocation},
      .capabilities = {.non_uniform = Support::yes, .noise = Support::yes, .outliers = Support::yes,
                       .manifold = Support::no, .open = Support::yes, .multiple = Support::yes,
                       .sharp = Support::no, .guarantee = true, .time_complexity = "O(n log n)"},
      .condition = {.statement = "none"},
      .reconstruct = [](std::span<const Point> points, const Parameter_values& values) {
        return optimal_transport_reconstruction(
            points, {.vertices = static_cast<std::size_t>(values[vertices]),
                     .tolerance = values[tolerance],
                     .relocation = static_cast<unsigned>(values[relocation])});
      },
      .simplifies = true,
      .repeatable = false,
  };
}

}  // namespace curvebench::algorithms
