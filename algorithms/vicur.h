// VICUR (Nguyen, Zeng 2008, "VICUR: A human-vision-based algorithm for curve
// reconstruction", Robotics and Computer-Integrated Manufacturing 24, 824-834; survey,
// "Curve Generation based on Human Visual System", Table 1 group "HVS Based"):
//   DISCUR's shortest-first path growth over the Delaunay edges (discur.h), with a
//   "vision function" of proximity and good continuation: an edge at a path end must be
//   near enough for the path and must not turn sharply, unless it is short (a corner).
//
// Only VICUR's abstract could be read here, so this is NOT the paper's vision function:
// it is DISCUR extended by a continuation rule in its spirit, with four parameters as the
// survey's Table 1 counts (their names and defaults are ours):
//   proximity_ratio        an edge at a path end joins if |pq| <= ratio * the path's
//                          longest edge (DISCUR fixes 2);
//   turning_angle          degrees: a path turning at its end by more than this is
//                          taking a corner (180 turns continuation off, = DISCUR);
//   corner_ratio           a corner edge joins only if |pq| <= ratio * the end edge;
//   closing_rank           a path closes if its ends are among each other's k nearest.
// Every test is an exact polynomial sign; the turning test compares with the double
// nearest cos(turning_angle) (exactly 0 at 90 degrees). Same complexity as DISCUR.
#pragma once

#include <span>
#include <vector>

#include "algorithms/algorithm.h"

namespace curvebench::algorithms {

// The default proximity_ratio, here and in the registry: DISCUR's fixed 2.
inline constexpr double default_vicur_proximity_ratio = 2;
// The default turning_angle, in degrees.
inline constexpr double default_vicur_turning_angle = 90;
// The default corner_ratio.
inline constexpr double default_vicur_corner_ratio = 1.5;
// The default closing_rank: a path closes if its ends are among each other's 2 nearest.
inline constexpr int default_vicur_closing_rank = 2;

// The VICUR edges on distinct points, canonical (i < j, sorted, no repeats). Throws
// std::invalid_argument for equal points, a non-finite coordinate or a parameter out of
// range (ratios <= 0, angle outside [0, 180], rank outside [1, 64]).
std::vector<Edge> vicur_reconstruction(std::span<const Point> points,
                                       double proximity_ratio = default_vicur_proximity_ratio,
                                       double turning_angle = default_vicur_turning_angle,
                                       double corner_ratio = default_vicur_corner_ratio,
                                       int closing_rank = default_vicur_closing_rank);
// The registry's entry "vicur", with parameters proximity_ratio, turning_angle, corner_ratio
// and closing_rank.
Algorithm vicur_algorithm();

}  // namespace curvebench::algorithms
