#include "algorithms/nn_crust.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <utility>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include "geometry/exact_sign.h"
#include "graphs/delaunay_triangulation.h"
#include "graphs/point_kd_tree.h"
#include "graphs/proximity_predicates.h"

namespace curvebench::algorithms {
namespace {

using geometry::certain_sign_of_difference;
using geometry::squared_distance_approximation;
using graphs::compare_distances;
using Index = std::uint32_t;

// The fallback's structure: CGAL's triangulation itself. Each vertex carries the index of
// its point and its rank in the insertion order, which indexes the search's marks.
struct Vertex_info {
  Index index = 0;
  Index id = 0;
};
using Kernel = geometry::Kernel;
using Vertex_base = CGAL::Triangulation_vertex_base_with_info_2<Vertex_info, Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<Vertex_base>;
using Triangulation = CGAL::Delaunay_triangulation_2<Kernel, Tds>;
using Vertex_handle = Triangulation::Vertex_handle;

// Whether s lies in the open half-plane of p with nearest neighbour q, given the
// approximate squared distances |pq|^2, |ps|^2 and |qs|^2.
bool in_half_plane(Half_plane half_plane, const Point& p, const Point& q, double pq2, const Point& s, double ps2,
                   double qs2) {
  if (half_plane == Half_plane::behind_p) {
    // 2 (s - p).(q - p) = |ps|^2 + |pq|^2 - |qs|^2: a comparison of sums of squares.
    if (const auto sign = certain_sign_of_difference(ps2 + pq2, qs2)) return *sign == CGAL::POSITIVE;
    using geometry::difference, geometry::dot;
    return geometry::exact_sign([&]<class NT>(std::type_identity<NT>) {
             return dot(difference<NT>(s, p), difference<NT>(q, p));
           }) == CGAL::NEGATIVE;
  }
  return compare_distances(s, p, ps2, q, qs2) == CGAL::POSITIVE;
}

// True if box b certainly holds no point of the open half-plane of p with nearest
// neighbour q. Both half-planes are {x : f(x) < 0} for an affine f increasing along q - p
// (behind_p: f(x) = (x - p).(q - p); beyond_bisector: f(x) = |xp|^2 - |xq|^2 =
// 2 (x - p).(q - p) - |pq|^2), so it suffices that f is certainly positive at the corner of
// b farthest back along q - p. The corners are input coordinates, so the error bound holds.
bool outside_half_plane(Half_plane half_plane, const Point& p, const Point& q, const graphs::Kd_box& b) {
  using geometry::Error_bounded_double;
  const Error_bounded_double ux = Error_bounded_double(q.x()) - p.x(), uy = Error_bounded_double(q.y()) - p.y();
  const Error_bounded_double x = Error_bounded_double(q.x() > p.x() ? b.xmin : b.xmax) - p.x();
  const Error_bounded_double y = Error_bounded_double(q.y() > p.y() ? b.ymin : b.ymax) - p.y();
  Error_bounded_double f = x * ux + y * uy;
  if (half_plane == Half_plane::beyond_bisector) f = (f + f) - (ux * ux + uy * uy);
  return f.sign_is_certain() && f.sign() == CGAL::POSITIVE;
}

// True if v lies at least |pr| from the line pq: cross(q - p, v - p)^2 >= |pr|^2 |pq|^2.
bool far_from_line(const Point& p, const Point& q, const Point& v, const Point& r) {
  using geometry::cross, geometry::difference, geometry::squared_length;
  return geometry::exact_sign([&]<class NT>(std::type_identity<NT>) {
           const auto u = difference<NT>(q, p);
           const NT c = cross(u, difference<NT>(v, p));
           return c * c - squared_length(difference<NT>(r, p)) * squared_length(u);
         }) != CGAL::NEGATIVE;
}

// The search on the triangulation, one vertex at a time: its neighbours in counterclockwise
// order, every decision by exact predicate, rules on each wedge (ring_proves) and, where
// they fail, a search outwards.
class Neighbor_search {
 public:
  Neighbor_search(const Triangulation& dt, Half_plane half_plane, std::vector<Nearest_and_half_neighbor>& result)
      : dt_(dt), half_plane_(half_plane), result_(result) {}

  void run() {
    for (const Vertex_handle v : dt_.finite_vertex_handles()) search_exactly(v);
  }

 private:

  // A point seen from p: approximate squared distances to p and to p's nearest neighbour q,
  // and what the search decided about it.
  struct Seen {
    Vertex_handle vertex;  // the infinite vertex for the unbounded side of a hull point
    const Point* point = nullptr;
    double to_p = 0, to_q = 0;
    Index index = 0;
    bool finite = false;
    bool in_half_plane = false;
    bool closer = false;  // strictly closer to p than the candidate half neighbour
  };

  // key(a) < key(b): a strictly closer to p, or as close with the smaller index.
  bool precedes(const Seen& a, const Seen& b) const {
    const CGAL::Sign s = compare_distances(*p_, *a.point, a.to_p, *b.point, b.to_p);
    return s == CGAL::POSITIVE || (s == CGAL::ZERO && a.index < b.index);
  }

  // The neighbour of p that comes first among those `eligible`, or npos.
  template <class Eligible>
  std::size_t first_in_ring(Eligible eligible) const {
    std::size_t best = npos;
    for (std::size_t k = 0; k < ring_.size(); ++k)
      if (ring_[k].finite && eligible(ring_[k]) && (best == npos || precedes(ring_[k], ring_[best]))) best = k;
    return best;
  }

  void classify(Seen& w) const {
    w.to_q = squared_distance_approximation(*q_, *w.point);
    w.in_half_plane = in_half_plane(half_plane_, *p_, *q_, q_to_p_, *w.point, w.to_p, w.to_q);
  }

  // Why the wedges around p can prove that no point beyond them comes before the
  // candidate r (the first neighbour of p in the half-plane). Every point s that is not a
  // neighbour of p lies beyond the link edge ab of a triangle pab, in the cone at p spanned
  // by a and b, outside the (empty) circumcircle; the distance from p to that circle along
  // the cone is smallest at a or b, so |ps| > min(|pa|, |pb|). So the wedge pab hides
  // nothing that comes before r when
  //   1. neither a nor b is strictly closer to p than r; or
  //   2. neither a nor b is in the half-plane: the half-plane's boundary then separates
  //      segment ab, and everything beyond it in the cone, from p's side (both half-planes
  //      are {x : f(x) < 0} for an affine f with f(p) <= 0); or
  //   3. a = q and b is in the half-plane at least |pr| from the line pq: the circle
  //      through p, q, b meets the line through p perpendicular to pq (NN-Crust) at
  //      distance 2t > dist(b, pq) from p, and pq's bisector (HNN-Crust; a diameter of that
  //      circle) at distance > dist(b, pq), so the part of the cone in the half-plane and
  //      outside the circle lies farther from p than min(dist(b, pq), |pb|) >= |pr|.
  // Wedges at the infinite vertex are outside the convex hull, where there is no point.
  bool ring_proves(std::size_t q_at, std::size_t r_at) const {
    const std::size_t m = ring_.size();
    for (std::size_t k = 0; k < m; ++k) {
      const std::size_t next = k + 1 == m ? 0 : k + 1;
      const Seen &a = ring_[k], &b = ring_[next];
      if (!a.finite || !b.finite) continue;
      if (!a.in_half_plane && !b.in_half_plane) continue;
      if (r_at == npos) return false;
      if (!a.closer && !b.closer) continue;
      const Point& r = *ring_[r_at].point;
      if (k == q_at && b.in_half_plane && far_from_line(*p_, *q_, *b.point, r)) continue;
      if (next == q_at && a.in_half_plane && far_from_line(*p_, *q_, *a.point, r)) continue;
      return false;
    }
    return true;
  }

  Seen see(Vertex_handle v) const {
    Seen s;
    s.vertex = v;
    s.point = &v->point();
    s.to_p = squared_distance_approximation(*p_, v->point());
    s.index = v->info().index;
    s.finite = true;
    return s;
  }

  void search_exactly(Vertex_handle p) {
    p_ = &p->point();
    ring_.clear();
    auto c = dt_.incident_vertices(p);
    const auto done = c;
    do {
      if (dt_.is_infinite(c)) {
        ring_.emplace_back();
        ring_.back().vertex = c;
      } else {
        ring_.push_back(see(c));
      }
    } while (++c != done);

    const std::size_t q_at = first_in_ring([](const Seen&) { return true; });
    q_ = ring_[q_at].point;
    q_to_p_ = ring_[q_at].to_p;
    for (std::size_t k = 0; k < ring_.size(); ++k)
      if (ring_[k].finite && k != q_at) classify(ring_[k]);
    const std::size_t r_at = first_in_ring([](const Seen& w) { return w.in_half_plane; });
    if (r_at != npos) {
      const Seen& r = ring_[r_at];
      for (Seen& w : ring_)
        w.closer = w.finite && w.index != r.index &&
                   compare_distances(*p_, *w.point, w.to_p, *r.point, r.to_p) == CGAL::POSITIVE;
    }
    Nearest_and_half_neighbor& out = result_[p->info().index];
    out.nearest = ring_[q_at].index;
    if (ring_proves(q_at, r_at)) {
      if (r_at != npos) out.half = ring_[r_at].index;
      return;
    }
    // ring_proves fails without a candidate only if a neighbour lies in the half-plane,
    // which would be a candidate: r_at is set here.
    Seen r = ring_[r_at];
    search_outwards(p, r);
    out.half = r.index;
  }

  // Breadth-first through the points strictly closer to p than the candidate r. Every point
  // s has a Delaunay neighbour strictly closer to p, or p itself (grow the circle through s
  // tangent inside the disk centred at p until it meets a point), so this reaches every
  // point that could come before r.
  void search_outwards(Vertex_handle p, Seen& r) {
    if (seen_by_.empty()) seen_by_.assign(dt_.number_of_vertices(), no_neighbor);
    const Index stamp = p->info().id;
    seen_by_[stamp] = stamp;
    queue_.clear();
    for (const Seen& w : ring_) {
      if (!w.finite) continue;
      seen_by_[w.vertex->info().id] = stamp;
      if (w.closer) queue_.push_back(w.vertex);
    }
    for (std::size_t head = 0; head < queue_.size(); ++head) {
      const Vertex_handle x = queue_[head];
      const Seen seen_x = see(x);
      if (compare_distances(*p_, *seen_x.point, seen_x.to_p, *r.point, r.to_p) != CGAL::POSITIVE) continue;
      auto c = dt_.incident_vertices(x);
      const auto done = c;
      do {
        if (dt_.is_infinite(c) || seen_by_[c->info().id] == stamp) continue;
        seen_by_[c->info().id] = stamp;
        Seen s = see(c);
        classify(s);
        if (s.in_half_plane) {
          if (precedes(s, r)) r = s;
        } else if (compare_distances(*p_, *s.point, s.to_p, *r.point, r.to_p) == CGAL::POSITIVE) {
          queue_.push_back(c);
        }
      } while (++c != done);
    }
  }

  static constexpr std::size_t npos = std::size_t(-1);

  const Triangulation& dt_;
  Half_plane half_plane_;
  std::vector<Nearest_and_half_neighbor>& result_;
  std::vector<Index> seen_by_;  // by vertex id  // the vertex whose outward search has seen this one
  // The exact search of one vertex p:
  const Point* p_ = nullptr;
  const Point* q_ = nullptr;
  double q_to_p_ = 0;
  std::vector<Seen> ring_;  // p's neighbours in counterclockwise order, reused
  std::vector<Vertex_handle> queue_;
};

// All points on one line: each point's neighbours along it.
void collinear_neighbors(std::span<const Point> points, std::vector<Nearest_and_half_neighbor>& result) {
  std::vector<Index> order(points.size());
  std::iota(order.begin(), order.end(), Index{0});
  // Lexicographic order is the order along the line, whatever its direction.
  std::sort(order.begin(), order.end(), [&](Index a, Index b) { return points[a] < points[b]; });
  if (std::adjacent_find(order.begin(), order.end(), [&](Index a, Index b) { return points[a] == points[b]; }) !=
      order.end())
    throw std::invalid_argument("nearest and half neighbours: two points are equal; merge duplicates first");
  for (std::size_t k = 0; k < order.size(); ++k) {
    const Index p = order[k];
    const Index before = k > 0 ? order[k - 1] : no_neighbor, after = k + 1 < order.size() ? order[k + 1] : no_neighbor;
    Index nearest = before == no_neighbor ? after : before, other = before == no_neighbor ? no_neighbor : after;
    if (other != no_neighbor && graphs::closer(points[p], points[other], other, points[nearest], nearest))
      std::swap(nearest, other);
    // The other neighbour lies opposite the nearest one, so in either half-plane; points
    // beyond the nearest one lie in neither.
    result[p] = {nearest, other};
  }
}

// Each point's two neighbours from two exact queries of a kd-tree (graphs/point_kd_tree.h),
// or nothing if the tree's work limit ran out (points packed far below their spread).
std::optional<std::vector<Nearest_and_half_neighbor>> neighbors_from_kd_tree(std::span<const Point> points,
                                                                             Half_plane half_plane) {
  graphs::Point_kd_tree tree(points);
  std::vector<Nearest_and_half_neighbor> result(points.size());
  const auto anywhere = [](Index) { return true; };
  const auto nowhere = [](const graphs::Kd_box&) { return false; };
  for (Index rank = 0; rank < points.size(); ++rank) {
    const Index p = tree.leaf_order()[rank];
    const std::optional<Index> q = tree.nearest(rank, anywhere, nowhere);
    if (!q) return std::nullopt;
    const Point &pp = points[p], &pq = points[*q];
    if (pp == pq) throw std::invalid_argument("nearest and half neighbours: two points are equal; merge duplicates first");
    const double pq2 = squared_distance_approximation(pp, pq);
    const auto in_half = [&](Index s) {
      const Point& ps = points[s];
      return in_half_plane(half_plane, pp, pq, pq2, ps, squared_distance_approximation(pp, ps),
                           squared_distance_approximation(pq, ps));
    };
    const auto outside = [&](const graphs::Kd_box& box) { return outside_half_plane(half_plane, pp, pq, box); };
    const std::optional<Index> half = tree.nearest(rank, in_half, outside);
    if (!half) return std::nullopt;
    result[p] = {*q, *half};
  }
  return result;
}

}  // namespace

std::vector<Nearest_and_half_neighbor> nearest_and_half_neighbors(std::span<const Point> points, Half_plane half_plane,
                                                                   Search_structure structure) {
  if (points.size() >= no_neighbor) throw std::invalid_argument("nearest and half neighbours: too many points");
  for (const Point& p : points)
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
      throw std::invalid_argument("nearest and half neighbours: a coordinate is not finite");
  if (points.size() < 2) return std::vector<Nearest_and_half_neighbor>(points.size());
  if (structure == Search_structure::kd_tree && graphs::Point_kd_tree::usable(points))
    if (auto found = neighbors_from_kd_tree(points, half_plane)) return std::move(*found);

  std::vector<Nearest_and_half_neighbor> result(points.size());
  if (graphs::all_collinear(points)) {
    collinear_neighbors(points, result);
    return result;
  }

  // Hilbert-sort the (point, index) pairs themselves and insert each with the previous
  // vertex as hint: CGAL's range insertion, minus the indirection through an index array.
  std::vector<std::pair<Point, Index>> indexed;
  indexed.reserve(points.size());
  for (Index i = 0; i < points.size(); ++i) indexed.emplace_back(points[i], i);
  CGAL::spatial_sort(indexed.begin(), indexed.end(),
                     CGAL::Spatial_sort_traits_adapter_2<Kernel, CGAL::First_of_pair_property_map<std::pair<Point, Index>>>());
  Triangulation dt;
  Triangulation::Face_handle hint;
  for (Index id = 0; id < indexed.size(); ++id) {
    const Vertex_handle v = dt.insert(indexed[id].first, hint);
    v->info() = {indexed[id].second, id};
    hint = v->face();
  }
  if (dt.number_of_vertices() != points.size())
    throw std::invalid_argument("nearest and half neighbours: two points are equal; merge duplicates first");

  Neighbor_search(dt, half_plane, result).run();
  return result;
}

std::vector<Edge> nn_crust_reconstruction(std::span<const Point> points) {
  const std::vector<Nearest_and_half_neighbor> neighbors = nearest_and_half_neighbors(points, Half_plane::behind_p);
  const auto lists = [&](Index i, Index j) { return neighbors[i].nearest == j || neighbors[i].half == j; };
  // An edge chosen from both ends is emitted at its smaller end, which visits the ends in
  // order; one chosen from one end only goes to a side list, sorted and merged in.
  std::vector<Edge> both, one;
  both.reserve(points.size() + 1);
  for (Index i = 0; i < neighbors.size(); ++i) {
    Index a = neighbors[i].nearest, b = neighbors[i].half;
    if (a > b) std::swap(a, b);
    for (const Index j : {a, b}) {
      if (j == no_neighbor) continue;
      if (!lists(j, i))
        one.emplace_back(std::min(i, j), std::max(i, j));
      else if (i < j)
        both.emplace_back(i, j);
    }
  }
  if (one.empty()) return both;
  std::sort(one.begin(), one.end());
  std::vector<Edge> edges(both.size() + one.size());
  std::merge(both.begin(), both.end(), one.begin(), one.end(), edges.begin());
  return edges;
}

Algorithm nn_crust_algorithm() {
  return {
      .name = "nn-crust",
      .title = "NN-Crust",
      .reference = "Dey, Kumar 1999",
      .category = "Feature Size Criteria",
      .parameters = {},
      .capabilities = {.non_uniform = Support::yes, .manifold = Support::yes, .open = Support::yes,
                       .multiple = Support::yes, .guarantee = true, .time_complexity = "O(n log n)"},
      .condition = {.statement = "epsilon < 1/3", .epsilon_below = 1.0 / 3, .rho_below = {}, .corner_angle_above = {}},
      .reconstruct = edges_on_input(nn_crust_reconstruction),
  };
}

}  // namespace curvebench::algorithms
