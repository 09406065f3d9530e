// The exact predicates behind the proximity graphs: "does point r block edge pq?".
//
// Each is a polynomial sign in the input coordinates (geometry/exact_sign.h), so no
// decision depends on a rounded length, angle or circle centre.
#pragma once

#include <cstdint>

#include "geometry/exact_sign.h"
#include "geometry/kernel.h"

namespace curvebench::graphs {

using geometry::Point;

// The sign of |cd|^2 - |ab|^2 given both squared lengths rounded
// (geometry::squared_distance_approximation), as sorts and queues keep them: POSITIVE if
// segment ab is shorter than cd.
inline CGAL::Sign compare_lengths(const Point& a, const Point& b, double ab2, const Point& c, const Point& d,
                                  double cd2) {
  if (const auto s = geometry::certain_sign_of_difference(ab2, cd2)) return *s;
  // Lengths equal to 15 digits, as on an evenly sampled curve: finer sums settle all but
  // the closest few without the exact stages.
  if (const auto s = geometry::certain_sign_of_difference(geometry::refined_squared_distance(a, b),
                                                          geometry::refined_squared_distance(c, d)))
    return *s;
  using geometry::difference, geometry::squared_length;
  return geometry::exact_sign([&]<class NT>(std::type_identity<NT>) {
    return squared_length(difference<NT>(d, c)) - squared_length(difference<NT>(b, a));
  });
}

// The same, rounding the two squared lengths first.
inline CGAL::Sign compare_lengths(const Point& a, const Point& b, const Point& c, const Point& d) {
  using geometry::squared_distance_approximation;
  return compare_lengths(a, b, squared_distance_approximation(a, b), c, d, squared_distance_approximation(c, d));
}

// The sign of |pb|^2 - |pa|^2: POSITIVE if a is closer to p than b.
inline CGAL::Sign compare_distances(const Point& p, const Point& a, const Point& b) {
  return compare_lengths(p, a, p, b);
}
// The same, given both squared distances rounded (geometry::squared_distance_approximation).
inline CGAL::Sign compare_distances(const Point& p, const Point& a, double pa2, const Point& b, double pb2) {
  return compare_lengths(p, a, pa2, p, b, pb2);
}

// The sign of (p - r).(q - r): POSITIVE if the angle prq is acute, ZERO if right, NEGATIVE
// if obtuse. 2 (p - r).(q - r) = |rp|^2 + |rq|^2 - |pq|^2, a comparison of sums of squares
// that the cheap filter almost always decides.
inline CGAL::Sign angle_sign(const Point& p, const Point& q, const Point& r) {
  using geometry::squared_distance_approximation;
  if (const auto s = geometry::certain_sign_of_difference(
          squared_distance_approximation(p, q),
          squared_distance_approximation(r, p) + squared_distance_approximation(r, q)))
    return *s;
  using geometry::difference, geometry::dot;
  return geometry::exact_sign(
      [&]<class NT>(std::type_identity<NT>) { return dot(difference<NT>(p, r), difference<NT>(q, r)); });
}

// True if a is strictly closer to p than b; at equal distance, the smaller index wins.
// This total order makes nearest neighbours, kNN and the EMST unique.
inline bool closer(const Point& p, const Point& a, std::uint32_t a_index, const Point& b,
                   std::uint32_t b_index) {
  const auto s = compare_distances(p, a, b);
  return s == CGAL::POSITIVE || (s == CGAL::ZERO && a_index < b_index);
}

// The two shapes of the beta-skeleton's forbidden region for beta > 1 (survey,
// "Proximity Graphs"; Kirkpatrick and Radke 1985). For beta <= 1 they coincide.
enum class Beta_region {
  lune,    // intersection of two disks of diameter beta|pq|, centred on the line pq
  circle,  // union of two disks of diameter beta|pq| passing through p and q
};

// True if r lies in the region R_beta(p, q) that keeps edge pq out of the beta-skeleton:
//   beta < 1: the closed lens { r : angle prq >= pi - arcsin(beta) }, minus p and q
//             (at beta = 0, the segment pq);
//   beta = 1: the closed disk with diameter pq (Gabriel and Sokal's definition: a point
//             on the circle blocks, which keeps the Gabriel graph inside every Delaunay
//             triangulation of cocircular points);
//   beta > 1: the open lune or the open union of circles (at beta = 2 the lune is the
//             relative neighbourhood graph's, Toussaint's definition, which keeps the
//             edges of an equilateral triangle).
// The closed disk of diameter pq lies in R_beta for every beta >= 1, so the family is
// monotone: a larger beta removes more edges.
// The conditions are written as polynomials: with u = p - r, v = q - r, the angle prq
// exceeds theta (sin theta = 1/beta) iff u.v <= 0 or (u.v)^2 < (beta^2 - 1)(u x v)^2.
inline bool blocks(const Point& p, const Point& q, const Point& r, double beta, Beta_region region) {
  // The relative neighbourhood graph's lune contains the closed diametral disk (minus p
  // and q): two distance comparisons decide, on the hottest path of RNG and EMST laws.
  if (beta == 2 && region == Beta_region::lune)
    return compare_lengths(r, p, p, q) == CGAL::POSITIVE && compare_lengths(r, q, p, q) == CGAL::POSITIVE;
  using geometry::cross, geometry::difference, geometry::dot, geometry::exact_sign, geometry::squared_length;
  const CGAL::Sign angle_cosine_sign = angle_sign(p, q, r);
  if (beta < 1) {
    return angle_cosine_sign == CGAL::NEGATIVE &&
           exact_sign([&]<class NT>(std::type_identity<NT>) {
             const auto u = difference<NT>(p, r), v = difference<NT>(q, r);
             const NT b2 = NT(beta) * NT(beta);
             return b2 * dot(u, v) * dot(u, v) - (NT(1) - b2) * cross(u, v) * cross(u, v);
           }) != CGAL::NEGATIVE;
  }
  if (angle_cosine_sign != CGAL::POSITIVE) return true;  // closed diametral disk
  if (beta == 1) return false;
  if (region == Beta_region::circle) {
    return exact_sign([&]<class NT>(std::type_identity<NT>) {
             const auto u = difference<NT>(p, r), v = difference<NT>(q, r);
             return (NT(beta) * NT(beta) - NT(1)) * cross(u, v) * cross(u, v) - dot(u, v) * dot(u, v);
           }) == CGAL::POSITIVE;
  }
  // r is inside the disk centred at p + beta/2 (q - p) through p iff |r-p|^2 < beta (r-p).(q-p).
  const auto inside_disk_through = [&](const Point& a, const Point& b) {
    return exact_sign([&]<class NT>(std::type_identity<NT>) {
             const auto w = difference<NT>(r, a);
             return NT(beta) * dot(w, difference<NT>(b, a)) - squared_length(w);
           }) == CGAL::POSITIVE;
  };
  return inside_disk_through(p, q) && inside_disk_through(q, p);
}

// True if r lies in the open disk centred at the midpoint of pq with radius
// |pq| sqrt(2 beta - 1) / 2, which contains the lune R_beta(p, q) for beta >= 1:
// summing the two disk conditions of the lune gives |rp|^2 + |rq|^2 < beta |pq|^2.
inline bool in_lune_hull(const Point& p, const Point& q, const Point& r, double beta) {
  using geometry::difference, geometry::squared_distance_approximation, geometry::squared_length;
  if (const auto s = geometry::certain_sign_of_difference(
          squared_distance_approximation(r, p) + squared_distance_approximation(r, q),
          beta * squared_distance_approximation(p, q)))
    return *s == CGAL::POSITIVE;
  return geometry::exact_sign([&]<class NT>(std::type_identity<NT>) {
           return NT(beta) * squared_length(difference<NT>(q, p)) - squared_length(difference<NT>(r, p)) -
                  squared_length(difference<NT>(r, q));
         }) == CGAL::POSITIVE;
}

// Sphere-of-influence test (Toussaint 1988): with r_p = |p p'| and r_q = |q q'| the
// nearest-neighbour distances, |pq| <= r_p + r_q. Squaring twice keeps it polynomial:
// c <= a + b  iff  c^2 - a^2 - b^2 <= 0  or  (c^2 - a^2 - b^2)^2 <= 4 a^2 b^2.
inline bool spheres_of_influence_meet(const Point& p, const Point& p_nearest, const Point& q,
                                      const Point& q_nearest) {
  using geometry::difference, geometry::exact_sign, geometry::squared_length;
  const auto excess = [&]<class NT>(std::type_identity<NT>) {
    return squared_length(difference<NT>(q, p)) - squared_length(difference<NT>(p_nearest, p)) -
           squared_length(difference<NT>(q_nearest, q));
  };
  if (exact_sign(excess) != CGAL::POSITIVE) return true;
  return exact_sign([&]<class NT>(std::type_identity<NT>) {
           const NT e = excess(std::type_identity<NT>{});
           return NT(4) * squared_length(difference<NT>(p_nearest, p)) *
                      squared_length(difference<NT>(q_nearest, q)) -
                  e * e;
         }) != CGAL::NEGATIVE;
}

// True if |x - p| <= 2 |p - p_nearest|: the closed disk that holds every sphere-of-influence
// neighbour q of p with r_q <= r_p.
inline bool within_twice_nearest(const Point& p, const Point& p_nearest, const Point& x) {
  using geometry::difference, geometry::exact_sign, geometry::squared_distance_approximation, geometry::squared_length;
  if (const auto s = geometry::certain_sign_of_difference(squared_distance_approximation(x, p),
                                                          4 * squared_distance_approximation(p_nearest, p)))
    return *s == CGAL::POSITIVE;
  return exact_sign([&]<class NT>(std::type_identity<NT>) {
           return NT(4) * squared_length(difference<NT>(p_nearest, p)) - squared_length(difference<NT>(x, p));
         }) != CGAL::NEGATIVE;
}

}  // namespace curvebench::graphs
