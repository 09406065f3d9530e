// A kd-tree over points for exact nearest-point queries: the nearest point to a centre
// among those that pass an exact test, by exact squared distance, ties to the smaller
// index. The search is a filter around exact decisions: it prunes a box only when its
// rounded distance exceeds the rounded best by more than every rounding error could make
// up (relative 2^-40, absolute 2^-900), keeps every point within that margin of the best as
// a candidate, and ranks the candidates with exact predicates. So floating point decides
// only where to look, never the answer.
//
// Why not a Delaunay triangulation: a query needs the points near the centre, not the
// whole triangulation; the tree takes under a third of its memory and, on curves, a
// fraction of its time (nn_crust.h measures it). Why not CGAL's Spatial_searching: its
// distances are rounded, and a tie or a near-tie would then be decided by rounding.
//
// Bucket leaves of at most 8 points, split at the median of the wider side of a node's
// tight bounding box, so that curves (1-D sets in the plane) get boxes that hug them.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "geometry/kernel.h"
#include "graphs/proximity_predicates.h"

namespace curvebench::graphs {

/// An axis-parallel box of the tree: the tight bounds of the points of one node.
struct Kd_box {
  double xmin;  ///< the least x of its points
  double ymin;  ///< the least y of its points
  double xmax;  ///< the greatest x of its points
  double ymax;  ///< the greatest y of its points
};

/// A kd-tree over a span of points (kept, not copied: they must outlive the tree) for
/// exact nearest-point queries. Nothing changes after construction.
class Point_kd_tree {
 public:
  /// A point's index in the span the tree was built on.
  using Index = std::uint32_t;
  /// The index that stands for "no point".
  static constexpr Index none = std::numeric_limits<Index>::max();

  /// Builds the tree in O(n log n). The points must have finite coordinates of magnitude at
  /// most 2^400 (so that no squared distance overflows; usable() says whether they do).
  explicit Point_kd_tree(std::span<const geometry::Point> points);

  /// Whether coordinates this large and differences this small keep the search's rounded
  /// distances finite and above underflow: magnitudes at most 2^400 and a bounding box
  /// wider than 2^-400. On other points the margins stop pruning and queries soon give up.
  static bool usable(std::span<const geometry::Point> points);

  /// The point indices in leaf order: points near in space are mostly near here, so queries
  /// made in this order reuse the cache.
  std::span<const Index> leaf_order() const { return order_; }

  /// The nearest point s to the centre c = leaf_order()[rank], s != c, with eligible(s) (an
  /// exact test), by exact squared distance, ties to the smaller index; `none` if there is
  /// none. The centre is named by its rank in leaf order, where its coordinates are at
  /// hand. A box for which excludes(box) is true is not searched: it must hold no eligible
  /// point. Gives up (returns nothing) once the points examined by all queries of this tree
  /// exceed the work limit, so that a caller can bound the total work on adversarial input.
  template <class Eligible, class Excludes>
  std::optional<Index> nearest(Index rank, Eligible eligible, Excludes excludes);

  /// The limit on points examined, over all queries, after which nearest gives up
  /// (by default 256 per point plus 2^16).
  void set_work_limit(std::uint64_t limit) { work_limit_ = limit; }

 private:
  struct Node {
    Kd_box box;
    Index begin, end;  // the node's points: order_[begin, end)
    Index left;        // children left and left + 1; 0 for a leaf (the root is no child)
    Index parent;      // 0 for the root
  };
  struct Leaf_point {
    double x, y;
  };
  struct Item {
    double x, y;
    Index index;
  };

  void build(std::vector<Item>& items, Index node, Index begin, Index end);
  static double squared_distance_to_box(double x, double y, const Kd_box& b) {
    const double dx = std::max(std::max(b.xmin - x, x - b.xmax), 0.0);
    const double dy = std::max(std::max(b.ymin - y, y - b.ymax), 0.0);
    return dx * dx + dy * dy;
  }
  // The largest rounded squared distance at which a point could still be exactly as near
  // as one whose rounded squared distance is `best`.
  static double margin(double best) { return best * (1 + 0x1p-40) + 0x1p-900; }

  std::span<const geometry::Point> points_;
  std::vector<Index> order_;
  std::vector<Leaf_point> coordinates_;  // the points of order_, in that order
  std::vector<Node> nodes_;
  std::vector<Index> leaf_of_;  // by rank in order_: the leaf that holds the point
  std::uint64_t work_ = 0;
  std::uint64_t work_limit_;
  // Reused by each query.
  struct Candidate {
    double squared_distance;
    Index index;
  };
  std::vector<Candidate> candidates_;
};

template <class Eligible, class Excludes>
std::optional<Point_kd_tree::Index> Point_kd_tree::nearest(Index rank, Eligible eligible, Excludes excludes) {
  const Index center = order_[rank];
  const double cx = coordinates_[rank].x, cy = coordinates_[rank].y;
  double best = std::numeric_limits<double>::infinity();
  candidates_.clear();

  const auto scan_leaf = [&](const Node& leaf) {
    work_ += leaf.end - leaf.begin;
    for (Index k = leaf.begin; k < leaf.end; ++k) {
      const double dx = coordinates_[k].x - cx, dy = coordinates_[k].y - cy;
      const double d = dx * dx + dy * dy;
      if (d > margin(best)) continue;
      const Index s = order_[k];
      if (s == center || !eligible(s)) continue;
      candidates_.push_back({d, s});
      if (d < best) best = d;
    }
  };
  // Depth first below `root`, nearer child first; a node is pruned when popped if the best
  // has since moved below its box.
  struct Pending {
    Index node;
    double squared_distance;
  };
  std::array<Pending, 64> stack;  // at most one per level, plus one
  const auto search_below = [&](Index root) {
    const double d = squared_distance_to_box(cx, cy, nodes_[root].box);
    if (d > margin(best) || excludes(nodes_[root].box)) return;
    std::size_t top = 0;
    stack[top++] = {root, d};
    while (top > 0) {
      const Pending pending = stack[--top];
      if (pending.squared_distance > margin(best)) continue;
      const Node& node = nodes_[pending.node];
      if (node.left == 0) {
        scan_leaf(node);
        continue;
      }
      const Index a = node.left, b = node.left + 1;
      const double da = squared_distance_to_box(cx, cy, nodes_[a].box);
      const double db = squared_distance_to_box(cx, cy, nodes_[b].box);
      const bool a_first = da <= db;
      const Pending first{a_first ? a : b, a_first ? da : db}, second{a_first ? b : a, a_first ? db : da};
      if (second.squared_distance <= margin(best) && !excludes(nodes_[second.node].box)) stack[top++] = second;
      if (first.squared_distance <= margin(best) && !excludes(nodes_[first.node].box)) stack[top++] = first;
    }
  };

  // Upwards from the centre's own leaf, where the answer usually is: at each ancestor,
  // search its other child. Stop at an ancestor whose box holds the whole disk around the
  // centre within which a candidate may lie: every point outside is farther than the best.
  // (The squared clearance is rounded like a squared distance, so the margin covers it.)
  Index node = leaf_of_[rank];
  scan_leaf(nodes_[node]);
  while (node != 0) {
    if (work_ > work_limit_) return std::nullopt;
    const Index parent = nodes_[node].parent, left = nodes_[parent].left;
    search_below(node == left ? left + 1 : left);
    node = parent;
    const Kd_box& box = nodes_[node].box;
    const double clearance = std::min(std::min(cx - box.xmin, box.xmax - cx), std::min(cy - box.ymin, box.ymax - cy));
    if (clearance * clearance > margin(best)) break;
  }
  if (work_ > work_limit_) return std::nullopt;

  // Exactly the nearest of the points within the margin of the best.
  Index answer = none;
  double answer_distance = 0;
  const double limit = margin(best);
  for (const Candidate& s : candidates_) {
    if (s.squared_distance > limit) continue;
    if (answer == none) {
      answer = s.index;
      answer_distance = s.squared_distance;
      continue;
    }
    const CGAL::Sign sign =
        compare_distances(points_[center], points_[s.index], s.squared_distance, points_[answer], answer_distance);
    if (sign == CGAL::POSITIVE || (sign == CGAL::ZERO && s.index < answer)) {
      answer = s.index;
      answer_distance = s.squared_distance;
    }
  }
  return answer;
}

}  // namespace curvebench::graphs
