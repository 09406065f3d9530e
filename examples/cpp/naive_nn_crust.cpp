// A naive NN-Crust (Dey and Kumar 1999) as an external curvebench algorithm, in plain C++17
// with no library: built outside curvebench's tree (CMakeLists.txt here), run as a program.
//
//   naive_nn_crust POINTS EDGES [HALF_ANGLE_DEGREES]
//
// reads "x y" lines and writes "i j" lines (0-based): each point is joined to its nearest
// neighbour q and to its half neighbour, the nearest point r with angle q-p-r above
// HALF_ANGLE_DEGREES (90 in the paper). O(n^2), in floating point: curvebench's own NN-Crust
// (algorithms/nn_crust.h) decides exactly, and `curvebench hunt` shows where that matters.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <set>
#include <string>
#include <utility>
#include <vector>

struct Point {
  double x, y;
};

int main(int argc, char** argv) {
  if (argc != 3 && argc != 4) {
    std::cerr << "usage: naive_nn_crust POINTS EDGES [HALF_ANGLE_DEGREES]\n";
    return 2;
  }
  const double half_angle = argc == 4 ? std::stod(argv[3]) : 90;
  const double cos_limit = std::cos(half_angle * M_PI / 180);
  std::vector<Point> points;
  std::ifstream in(argv[1]);
  for (Point p; in >> p.x >> p.y;) points.push_back(p);
  if (!in.eof()) {
    std::cerr << argv[1] << ": not 'x y' lines\n";
    return 1;
  }

  const auto distance2 = [&](std::size_t a, std::size_t b) {
    return std::pow(points[a].x - points[b].x, 2) + std::pow(points[a].y - points[b].y, 2);
  };
  std::set<std::pair<std::size_t, std::size_t>> edges;
  const auto join = [&](std::size_t a, std::size_t b) { edges.insert({std::min(a, b), std::max(a, b)}); };
  const std::size_t n = points.size(), none = n;
  for (std::size_t p = 0; p < n; ++p) {
    std::size_t q = none;
    for (std::size_t r = 0; r < n; ++r)
      if (r != p && (q == none || distance2(p, r) < distance2(p, q))) q = r;
    if (q == none) continue;
    join(p, q);
    // The half neighbour: the nearest r whose direction makes more than the angle with q's.
    std::size_t half = none;
    const double qx = points[q].x - points[p].x, qy = points[q].y - points[p].y;
    for (std::size_t r = 0; r < n; ++r) {
      if (r == p || r == q) continue;
      const double rx = points[r].x - points[p].x, ry = points[r].y - points[p].y;
      const double cosine = (qx * rx + qy * ry) / std::sqrt((qx * qx + qy * qy) * (rx * rx + ry * ry));
      if (cosine < cos_limit && (half == none || distance2(p, r) < distance2(p, half))) half = r;
    }
    if (half != none) join(p, half);
  }

  std::ofstream out(argv[2]);
  for (const auto& [i, j] : edges) out << i << ' ' << j << '\n';
  return out ? 0 : 1;
}
