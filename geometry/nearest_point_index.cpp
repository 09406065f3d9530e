#include "geometry/nearest_point_index.h"

#include <cmath>
#include <limits>

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_2.h>

namespace curvebench::geometry {
namespace {

using Search = CGAL::Orthogonal_k_neighbor_search<CGAL::Search_traits_2<Kernel>>;

}  // namespace

struct Nearest_point_index::Tree {
  explicit Tree(std::span<const Point> points) : tree(points.begin(), points.end()) {}
  Search::Tree tree;
};

Nearest_point_index::Nearest_point_index(std::span<const Point> points) : tree_(std::make_unique<Tree>(points)) {
  tree_->tree.build();  // a Kd-tree builds lazily on the first query: build now, so queries only read
}

Nearest_point_index::Nearest_point_index(Nearest_point_index&&) noexcept = default;
Nearest_point_index& Nearest_point_index::operator=(Nearest_point_index&&) noexcept = default;
Nearest_point_index::~Nearest_point_index() = default;

double Nearest_point_index::distance(const Point& query) const {
  if (tree_->tree.empty()) return std::numeric_limits<double>::infinity();
  const Search search(tree_->tree, query, 1);
  return std::sqrt(search.begin()->second);
}

}  // namespace curvebench::geometry
