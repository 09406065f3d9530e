#include "geometry/lfs/nearest_point_index.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace curvebench::geometry {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr std::uint32_t leaf_size = 16;
constexpr std::uint32_t no_point = std::numeric_limits<std::uint32_t>::max();
constexpr int maximum_depth = 64;  // median splits: depth <= log2(size) + 1 <= 33

// A subtree is skipped when its lower bound exceeds the best squared distance by this
// factor: both are rounded sums of two rounded squares, monotone in the coordinates'
// differences, so the bound never exceeds a point's squared distance; the factor only
// guards against a compiler contracting the two expressions into fused multiply-adds
// differently (a few ulps).
constexpr double prune_factor = 1 + 1e-12;

std::atomic<std::uint64_t> next_id{1};

// The last nearest point of the few indexes this thread queried last.
struct Guess {
  std::uint64_t id;
  std::uint32_t point;
};
constexpr int guess_slots = 4;
thread_local Guess guesses[guess_slots] = {};
thread_local unsigned next_guess_slot = 0;

}  // namespace

Nearest_point_index::Nearest_point_index(std::span<const Point> points) : id_(next_id.fetch_add(1)) {
  std::vector<Coordinates> kept;
  kept.reserve(points.size());
  // A point with a NaN coordinate is at NaN distance, nearer than nothing.
  for (const Point& p : points)
    if (!std::isnan(p.x()) && !std::isnan(p.y())) kept.push_back({p.x(), p.y()});
  if (kept.size() >= no_point) throw std::length_error("nearest point index: too many points");
  if (kept.empty()) return;
  nodes_.reserve(4 * kept.size() / leaf_size + 1);
  build(kept, 0, static_cast<std::uint32_t>(kept.size()));
  x_.reserve(kept.size());
  y_.reserve(kept.size());
  for (const Coordinates& p : kept) x_.push_back(p.x), y_.push_back(p.y);
}

std::uint32_t Nearest_point_index::build(std::vector<Coordinates>& points, std::uint32_t begin, std::uint32_t end) {
  const auto node = static_cast<std::uint32_t>(nodes_.size());
  double min_x = infinity, max_x = -infinity, min_y = infinity, max_y = -infinity;
  for (std::uint32_t i = begin; i < end; ++i) {
    min_x = std::min(min_x, points[i].x), max_x = std::max(max_x, points[i].x);
    min_y = std::min(min_y, points[i].y), max_y = std::max(max_y, points[i].y);
  }
  nodes_.push_back({min_x, min_y, max_x, max_y, begin, end, 0});
  if (end - begin <= leaf_size) return node;
  const std::uint32_t middle = begin + (end - begin) / 2;
  if (max_y - min_y > max_x - min_x)
    std::nth_element(points.begin() + begin, points.begin() + middle, points.begin() + end,
                     [](const Coordinates& p, const Coordinates& q) { return p.y < q.y; });
  else
    std::nth_element(points.begin() + begin, points.begin() + middle, points.begin() + end,
                     [](const Coordinates& p, const Coordinates& q) { return p.x < q.x; });
  build(points, begin, middle);
  nodes_[node].right = build(points, middle, end);
  return node;
}

double Nearest_point_index::nearest_squared_distance(double x, double y, std::uint32_t& nearest) const {
  // (x - px)² + (y - py)², as CGAL::squared_distance and CGAL's Kd-tree compute it.
  const auto squared_distance = [&](std::uint32_t i) {
    const double dx = x - x_[i], dy = y - y_[i];
    return dx * dx + dy * dy;
  };
  // A lower bound on the squared distances of a node's points, computed the same way on
  // the nearest point of its box: the differences, squares and sum are each rounded
  // monotonically, so it is at most any of its points' squared distances.
  const auto lower_bound = [&](const Node& n) {
    const double dx = std::max({n.min_x - x, x - n.max_x, 0.0}), dy = std::max({n.min_y - y, y - n.max_y, 0.0});
    return dx * dx + dy * dy;
  };
  if (nearest >= x_.size()) nearest = 0;
  double best = squared_distance(nearest);
  // Depth first, the nearer child first; the other one is pending with its bound.
  struct Pending {
    std::uint32_t node;
    double bound;
  };
  Pending stack[maximum_depth];
  int pending = 0;
  std::uint32_t node = 0;
  for (;;) {
    const Node* n = &nodes_[node];
    while (n->right != 0) {
      const std::uint32_t left = node + 1, right = n->right;
      const double left_bound = lower_bound(nodes_[left]), right_bound = lower_bound(nodes_[right]);
      const bool left_first = left_bound <= right_bound;
      const double near_bound = left_first ? left_bound : right_bound, far_bound = left_first ? right_bound : left_bound;
      if (near_bound > best * prune_factor) break;  // so is the far one
      if (!(far_bound > best * prune_factor)) stack[pending++] = {left_first ? right : left, far_bound};
      node = left_first ? left : right;
      n = &nodes_[node];
    }
    if (n->right == 0)
      for (std::uint32_t i = n->begin; i < n->end; ++i) {
        const double d = squared_distance(i);
        if (d < best) best = d, nearest = i;
      }
    for (;;) {
      if (pending == 0) return best;
      const Pending& next = stack[--pending];
      if (next.bound > best * prune_factor) continue;
      node = next.node;
      break;
    }
  }
}

double Nearest_point_index::distance(const Point& query) const {
  if (nodes_.empty()) return infinity;
  Guess* slot = nullptr;
  for (Guess& guess : guesses)
    if (guess.id == id_) slot = &guess;
  if (slot == nullptr) {
    slot = &guesses[next_guess_slot];
    next_guess_slot = (next_guess_slot + 1) % guess_slots;
    *slot = {id_, no_point};
  }
  return std::sqrt(nearest_squared_distance(query.x(), query.y(), slot->point));
}

}  // namespace curvebench::geometry
