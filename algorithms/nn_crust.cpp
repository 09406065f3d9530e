#include "algorithms/nn_crust.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <utility>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include "geometry/exact_sign.h"
#include "graphs/delaunay_triangulation.h"
#include "graphs/proximity_predicates.h"

namespace curvebench::algorithms {
namespace {

using geometry::certain_sign_of_difference;
using geometry::squared_distance_approximation;
using graphs::compare_distances;
using Index = std::uint32_t;

// CGAL's triangulation itself, not graphs::Delaunay_triangulation (flattening it to
// neighbour arrays costs a third of the triangulation). The fast path sweeps its faces in
// memory order, about an eighth of the triangulation's time at 10^6 points; walking around
// every vertex instead costs three to five times that, the faces around a vertex lying all
// over memory. Each vertex carries the index of its point and its rank in the (spatially
// sorted) insertion order, which indexes the arrays of the search.
struct Vertex_info {
  Index index = 0;
  Index id = 0;
};
using Kernel = geometry::Kernel;
using Vertex_base = CGAL::Triangulation_vertex_base_with_info_2<Vertex_info, Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<Vertex_base>;
using Triangulation = CGAL::Delaunay_triangulation_2<Kernel, Tds>;
using Vertex_handle = Triangulation::Vertex_handle;

constexpr double infinity = std::numeric_limits<double>::infinity();

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

// True if v lies at least |pr| from the line pq: cross(q - p, v - p)^2 >= |pr|^2 |pq|^2.
bool far_from_line(const Point& p, const Point& q, const Point& v, const Point& r) {
  using geometry::cross, geometry::difference, geometry::squared_length;
  return geometry::exact_sign([&]<class NT>(std::type_identity<NT>) {
           const auto u = difference<NT>(q, p);
           const NT c = cross(u, difference<NT>(v, p));
           return c * c - squared_length(difference<NT>(r, p)) * squared_length(u);
         }) != CGAL::NEGATIVE;
}

// Whether the approximations a < b of two squared distances (non-negative, a finite) prove
// the exact values in the same order: geometry::certain_sign_of_difference, inlined for
// the fast path; b infinite stands for "no such value" (overflow is caught before).
bool certainly_before(double a, double b) {
  if (b == infinity) return a < infinity;
  const double sum = a + b;
  return b - a > sum * 0x1p-48 && sum >= 0x1p-900;
}

// The two smallest approximate squared distances offered, with who offered them, and the
// third smallest: enough to name a vertex's nearest neighbour and, when the curve is
// sampled well, its half neighbour (its second nearest), and to bound how near its other
// neighbours can be. 32 bytes: the sweep that fills them is most of the fast path's time.
struct Nearest_two {
  double d[2] = {infinity, infinity};
  double third = infinity;
  Index id[2] = {no_neighbor, no_neighbor};

  // As selects rather than branches: the offers come in no predictable order.
  void offer(double x, Index by) {
    const bool c0 = x < d[0], c1 = x < d[1], c2 = x < third;
    third = c1 ? d[1] : c2 ? x : third;
    const double d1 = c0 ? d[0] : c1 ? x : d[1];
    const Index i1 = c0 ? id[0] : c1 ? by : id[1];
    d[0] = c0 ? x : d[0];
    id[0] = c0 ? by : id[0];
    d[1] = d1;
    id[1] = i1;
  }
};

class Neighbor_search {
 public:
  // `inserted`: the points with their indices, in the order of insertion, which numbered
  // the vertices (Vertex_info::id).
  Neighbor_search(const Triangulation& dt, std::span<const std::pair<Point, Index>> inserted, Half_plane half_plane,
                  std::vector<Nearest_and_half_neighbor>& result)
      : dt_(dt), inserted_(inserted), half_plane_(half_plane), result_(result) {}

  void run() {
    find_nearest_two();
    std::vector<bool> exact(inserted_.size(), overflow_);
    bool any_exact = overflow_;
    if (!overflow_)
      for (Index p = 0; p < inserted_.size(); ++p)
        if (!choose_neighbors(p)) exact[p] = any_exact = true;
    if (!any_exact) return;
    for (const Vertex_handle v : dt_.finite_vertex_handles())
      if (exact[v->info().id]) search_exactly(v);
  }

 private:
  // Fast path: one sweep over the faces in memory order and one over the vertices, with
  // floating-point filters that are certain or give up. Anything they cannot decide (ties,
  // overflow anywhere, a half neighbour that is not the second nearest, a neighbour of q
  // that might lead to a nearer point) sends the vertex to search_exactly.
  const Point& point(Index id) const { return inserted_[id].first; }
  Index index(Index id) const { return inserted_[id].second; }

  // Each vertex hears once from each neighbour: from the face that has the edge from the
  // vertex to the neighbour counterclockwise, which for some hull edges is an infinite face.
  void find_nearest_two() {
    nearest_.assign(inserted_.size(), Nearest_two{});
    const Vertex_handle infinite = dt_.infinite_vertex();
    const auto offer = [&](Vertex_handle u, Vertex_handle w) {
      const double d = squared_distance_approximation(u->point(), w->point());
      if (!(d < infinity)) overflow_ = true;  // the filters cannot rank it
      nearest_[u->info().id].offer(d, w->info().id);
    };
    for (const auto face : dt_.finite_face_handles()) {
      const Vertex_handle u = face->vertex(0), v = face->vertex(1), w = face->vertex(2);
      offer(u, v);
      offer(v, w);
      offer(w, u);
    }
    // The hull edges counterclockwise in the infinite faces.
    auto face = dt_.incident_faces(infinite);
    const auto done = face;
    do {
      const int i = face->index(infinite);
      offer(face->vertex(Triangulation::ccw(i)), face->vertex(Triangulation::cw(i)));
    } while (++face != done);
  }

  bool in_half_plane_of(Index p, Index q, double pq2, Index s, double ps2) const {
    const Point &pq = point(q), &pp = point(p), &ps = point(s);
    return in_half_plane(half_plane_, pp, pq, pq2, ps, ps2, squared_distance_approximation(pq, ps));
  }

  // The fast path's certificate that no point hides beyond p's neighbours. Every point s
  // has a Delaunay neighbour strictly closer to p, or p itself (search_outwards), so a point
  // s that is not p's neighbour and does not come after r starts a chain of points closer
  // than r that enters p's neighbours at one closer than r, which is q, from a neighbour t
  // of q that is not p's. So it suffices that every neighbour t of q is p, or p's second
  // nearest r, or comes after r: for t beyond q's two nearest, |qt|^2 >= third(q) >
  // 2 (|pq|^2 + |pr|^2) >= (|pq| + |pr|)^2 gives |pt| > |pr|; the two nearest are compared.
  bool chain_certificate(Index p, const Nearest_two& near) const {
    const Nearest_two& q = nearest_[near.id[0]];
    if (!certainly_before(2 * (near.d[0] + near.d[1]), q.third)) return false;
    const Point &pp = point(p), &pr = point(near.id[1]);
    for (const Index t : q.id) {
      if (t == no_neighbor || t == p || t == near.id[1]) continue;
      const Point& pt = point(t);
      const CGAL::Sign s = compare_distances(pp, pr, near.d[1], pt, squared_distance_approximation(pp, pt));
      if (s == CGAL::NEGATIVE || (s == CGAL::ZERO && index(t) < index(near.id[1]))) return false;
    }
    return true;
  }

  // Decides vertex p when its second nearest is its half neighbour, or returns false.
  bool choose_neighbors(Index p) {
    const Nearest_two& near = nearest_[p];
    if (near.id[1] == no_neighbor || !certainly_before(near.d[0], near.d[1]) ||
        !certainly_before(near.d[1], near.third) ||
        !in_half_plane_of(p, near.id[0], near.d[0], near.id[1], near.d[1]) || !chain_certificate(p, near))
      return false;
    result_[index(p)] = {index(near.id[0]), index(near.id[1])};
    return true;
  }

  // Exact path for one vertex: its neighbours in counterclockwise order, every decision by
  // exact predicate, rules on each wedge (ring_proves) and, where they fail, a search
  // outwards.

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
    if (seen_by_.empty()) seen_by_.assign(inserted_.size(), no_neighbor);
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
  std::span<const std::pair<Point, Index>> inserted_;  // by vertex id
  Half_plane half_plane_;
  std::vector<Nearest_and_half_neighbor>& result_;
  // By vertex id:
  std::vector<Nearest_two> nearest_;
  bool overflow_ = false;  // some squared distance overflowed: decide every vertex exactly
  std::vector<Index> seen_by_;  // the vertex whose outward search has seen this one
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

}  // namespace

std::vector<Nearest_and_half_neighbor> nearest_and_half_neighbors(std::span<const Point> points,
                                                                   Half_plane half_plane) {
  if (points.size() >= no_neighbor) throw std::invalid_argument("nearest and half neighbours: too many points");
  for (const Point& p : points)
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
      throw std::invalid_argument("nearest and half neighbours: a coordinate is not finite");
  std::vector<Nearest_and_half_neighbor> result(points.size());
  if (points.size() < 2) return result;
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

  Neighbor_search(dt, indexed, half_plane, result).run();
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
