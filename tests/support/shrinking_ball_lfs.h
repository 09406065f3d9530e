// An oracle for lfs that shares nothing with geometry/lfs: the medial axis as the centres
// of the maximal empty tangent balls of a dense sample of the curve, found by the
// shrinking-ball iteration (Ma, Bae, Kim 2012), and lfs(x) as the distance from x to the
// nearest centre. Its own sample (arc-length steps of at most `spacing`), its own
// nearest-neighbour search (CGAL's kd-tree), no Voronoi diagram.
//
// A ball tangent at sample p on the side of normal n starts at radius `start_radius`; while
// some other sample q lies inside it, it shrinks to the ball tangent at p through q,
// r = |pq|^2 / (2 n.(q - p)). A ball empty of the sample is at least as large as the one
// empty of the curve, so its centre lies on the medial axis or beyond it along the normal,
// by O(h^2 / r) for spacing h: the estimate converges to lfs as h -> 0. The exact corners
// of each component (Curve_component::corners()) are points of the medial axis' closure
// and are added as they are.
//
// Balls are computed only where a query needs them: the medial point m nearest to a curve
// point x (|xm| = lfs(x)) is the centre of a ball of radius at most |xm| touching the curve
// within 2 lfs(x) of x, so the balls of the samples within twice the best distance found
// so far settle it.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_2.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>

#include "geometry/curves/curve.h"

namespace curvebench::testing {

class Shrinking_ball_lfs {
 public:
  Shrinking_ball_lfs(const geometry::Curve& curve, double spacing, double start_radius)
      : spacing_(spacing), start_radius_(start_radius) {
    for (const geometry::Curve_component& component : curve.components) {
      const double length = component.length();
      // Steps of `spacing`, and of R / 64 where the radius of curvature R is smaller (down
      // to spacing / 1e4): where the curvature is unbounded (a Bézier end with its handle
      // on it) a ball empty of a sparser sample can hold much of the curve.
      for (double arc = 0; arc < length || (!component.closed() && arc == length);) {
        const double s = component.parameter_at_arc_length(arc);
        sample_.push_back(component.point(s));
        normals_.push_back(component.unit_normal(s));
        if (arc == length) break;
        const double radius = 1 / std::abs(component.curvature(s));
        arc = std::min(length, arc + std::clamp(radius / 64, spacing * 1e-4, spacing));
        if (component.closed() && arc >= length - spacing * 1e-4) break;
      }
      for (const double corner : component.corners()) centres_.push_back(component.point(corner));
    }
    const std::vector<std::size_t> all = indices(sample_.size());
    tree_.emplace(all.begin(), all.end(), Tree::Splitter(), Traits(Point_map(sample_.data())));
    done_.assign(sample_.size(), false);
  }

  // lfs(x) for a curve point x: its distance to the nearest ball centre (+infinity if none).
  double at(const geometry::Point& x) {
    double best = std::numeric_limits<double>::infinity();
    for (double reach = 16 * spacing_;; reach = std::max(2 * reach, 2.01 * best)) {
      for (std::size_t i = 0; i < sample_.size(); ++i)
        if (!done_[i] && CGAL::squared_distance(sample_[i], x) <= reach * reach) add_balls(i);
      for (const geometry::Point& centre : centres_) best = std::min(best, std::sqrt(CGAL::squared_distance(centre, x)));
      if (2 * best <= reach || reach > 4 * start_radius_) return best;
    }
  }

  std::size_t sample_size() const { return sample_.size(); }

 private:
  using Point = geometry::Point;
  using Point_map = CGAL::Pointer_property_map<Point>::const_type;
  using Traits = CGAL::Search_traits_adapter<std::size_t, Point_map, CGAL::Search_traits_2<geometry::Kernel>>;
  using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;
  using Tree = Search::Tree;

  static std::vector<std::size_t> indices(std::size_t n) {
    std::vector<std::size_t> all(n);
    for (std::size_t i = 0; i < n; ++i) all[i] = i;
    return all;
  }

  void add_balls(std::size_t i) {
    done_[i] = true;
    for (const double side : {1.0, -1.0}) {
      const geometry::Vector normal = side * normals_[i];
      if (const auto radius = shrink(i, normal)) centres_.push_back(sample_[i] + *radius * normal);
    }
  }

  // The radius of the ball tangent at sample i on the side of `normal`, shrunk from
  // start_radius until no other sample is inside; none if the first ball was empty.
  std::optional<double> shrink(std::size_t i, const geometry::Vector& normal) const {
    const Point& p = sample_[i];
    double radius = start_radius_;
    bool touched = false;
    for (int iteration = 0; iteration < 200; ++iteration) {
      const Search search(*tree_, p + radius * normal, 2, 0, true, Search::Distance(Point_map(sample_.data())));
      const Point* inside = nullptr;
      for (const auto& [j, squared] : search)
        if (j != i && sample_[j] != p) {
          if (std::sqrt(squared) < radius * (1 - 1e-12)) inside = &sample_[j];
          break;
        }
      if (inside == nullptr) break;
      const geometry::Vector pq = *inside - p;
      const double towards = normal * pq;
      if (!(towards > 0)) break;  // rounding: the sample sits on the ball's tangent line
      radius = (pq * pq) / (2 * towards);
      touched = true;
    }
    if (!touched) return std::nullopt;
    return radius;
  }

  double spacing_, start_radius_;
  std::vector<Point> sample_;
  std::vector<geometry::Vector> normals_;
  std::optional<Tree> tree_;
  std::vector<bool> done_;
  std::vector<Point> centres_;
};

}  // namespace curvebench::testing
