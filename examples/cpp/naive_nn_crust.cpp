// The naive NN-Crust of naive_nn_crust.h as an external curvebench algorithm, in plain C++17
// with no library: built outside curvebench's tree (CMakeLists.txt here), run as a program
// behind `exec:` (../algorithms.json).
//
//   naive_nn_crust POINTS EDGES [HALF_ANGLE_DEGREES]
//
// reads "x y" lines and writes "i j" lines (0-based).
#include <fstream>
#include <iostream>
#include <string>

#include "naive_nn_crust.h"

int main(int argc, char** argv) {
  if (argc != 3 && argc != 4) {
    std::cerr << "usage: naive_nn_crust POINTS EDGES [HALF_ANGLE_DEGREES]\n";
    return 2;
  }
  const double half_angle = argc == 4 ? std::stod(argv[3]) : 90;
  std::vector<naive::Point> points;
  std::ifstream in(argv[1]);
  for (naive::Point p; in >> p.x >> p.y;) points.push_back(p);
  if (!in.eof()) {
    std::cerr << argv[1] << ": not 'x y' lines\n";
    return 1;
  }
  std::ofstream out(argv[2]);
  for (const auto& [i, j] : naive::nn_crust(points, half_angle)) out << i << ' ' << j << '\n';
  return out ? 0 : 1;
}
