#include "graphs/point_kd_tree.h"

#include <algorithm>
#include <cmath>

namespace curvebench::graphs {
namespace {

constexpr Point_kd_tree::Index leaf_size = 8;

}  // namespace

bool Point_kd_tree::usable(std::span<const geometry::Point> points) {
  if (points.empty()) return true;
  double xmin = points[0].x(), xmax = xmin, ymin = points[0].y(), ymax = ymin;
  for (const geometry::Point& p : points) {
    xmin = std::min(xmin, p.x());
    xmax = std::max(xmax, p.x());
    ymin = std::min(ymin, p.y());
    ymax = std::max(ymax, p.y());
  }
  const double largest = std::max({std::abs(xmin), std::abs(xmax), std::abs(ymin), std::abs(ymax)});
  const double extent = std::max(xmax - xmin, ymax - ymin);
  return largest <= 0x1p400 && (points.size() < 2 || extent > 0x1p-400);
}

Point_kd_tree::Point_kd_tree(std::span<const geometry::Point> points)
    : points_(points), work_limit_(256 * std::uint64_t(points.size()) + (1u << 16)) {
  // Built on the coordinates themselves, not on indices into the points: the partitions
  // then run over contiguous memory.
  std::vector<Item> items;
  items.reserve(points.size());
  for (Index i = 0; i < points.size(); ++i) items.push_back({points[i].x(), points[i].y(), i});
  nodes_.reserve(2 * (points.size() / leaf_size) + 3);
  nodes_.push_back({});
  leaf_of_.resize(items.size());
  if (!items.empty()) build(items, 0, 0, Index(items.size()));
  order_.reserve(items.size());
  coordinates_.reserve(items.size());
  for (const Item& item : items) {
    order_.push_back(item.index);
    coordinates_.push_back({item.x, item.y});
  }
}

void Point_kd_tree::build(std::vector<Item>& items, Index node, Index begin, Index end) {
  Kd_box box{items[begin].x, items[begin].y, items[begin].x, items[begin].y};
  for (Index k = begin + 1; k < end; ++k)
    box = {std::min(box.xmin, items[k].x), std::min(box.ymin, items[k].y), std::max(box.xmax, items[k].x),
           std::max(box.ymax, items[k].y)};
  nodes_[node] = {box, begin, end, 0, nodes_[node].parent};
  if (end - begin <= leaf_size) {
    std::fill(leaf_of_.begin() + begin, leaf_of_.begin() + end, node);
    return;
  }

  const bool by_x = box.xmax - box.xmin >= box.ymax - box.ymin;
  const Index middle = begin + (end - begin) / 2;
  const auto first = items.begin() + begin, nth = items.begin() + middle, last = items.begin() + end;
  if (by_x)
    std::nth_element(first, nth, last, [](const Item& a, const Item& b) { return a.x < b.x; });
  else
    std::nth_element(first, nth, last, [](const Item& a, const Item& b) { return a.y < b.y; });
  const Index left = Index(nodes_.size());
  nodes_[node].left = left;
  nodes_.resize(nodes_.size() + 2);
  nodes_[left].parent = nodes_[left + 1].parent = node;
  build(items, left, begin, middle);
  build(items, left + 1, middle, end);
}

}  // namespace curvebench::graphs
