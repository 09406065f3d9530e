#include "algorithms/registry.h"

#include <algorithm>
#include <deque>
#include <mutex>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "algorithms/alpha_shape.h"
#include "algorithms/beta_skeleton.h"
#include "algorithms/connect2d.h"
#include "algorithms/conservative_crust.h"
#include "algorithms/crawl.h"
#include "algorithms/crust.h"
#include "algorithms/discur.h"
#include "algorithms/emst.h"
#include "algorithms/fit_connect.h"
#include "algorithms/gathan.h"
#include "algorithms/gathang.h"
#include "algorithms/hnn_crust.h"
#include "algorithms/lenz.h"
#include "algorithms/nn_crust.h"
#include "algorithms/optimal_transport.h"
#include "algorithms/outlier_filter.h"
#include "algorithms/peel.h"
#include "algorithms/shape_hull.h"
#include "algorithms/sig_connect2d.h"
#include "algorithms/stretch_denoise.h"
#include "algorithms/vicur.h"
#include "algorithms/voronoi_labeling.h"
#include "geometry/point_set.h"

namespace curvebench::algorithms {

namespace {

std::vector<Algorithm> built_in_algorithms() {
  return {
      alpha_shape_algorithm(),
      beta_skeleton_algorithm(),
      emst_algorithm(),
      connect2d_algorithm(),
      sig_connect2d_algorithm(),
      shape_hull_algorithm(),
      voronoi_labeling_algorithm(),
      crawl_algorithm(),
      crust_algorithm(),
      nn_crust_algorithm(),
      conservative_crust_algorithm(),
      lenz_algorithm(),
      hnn_crust_algorithm(),
      fit_connect_algorithm(),
      stretch_denoise_algorithm(),
      gathan_algorithm(),
      gathang_algorithm(),
      optimal_transport_algorithm(),
      peel_algorithm(),
      discur_algorithm(),
      vicur_algorithm(),
  };
}

struct Table {
  std::vector<Algorithm> algorithms = built_in_algorithms();
  const std::size_t built_in_count = algorithms.size();
  bool read = false;  // registration is closed once anyone may hold a pointer into it
};

Table& table() {
  static Table table;
  return table;
}

bool valid_name(std::string_view name) {
  return !name.empty() && !name.ends_with(outlier_filter_suffix) && std::ranges::all_of(name, [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.';
  });
}

// Throws std::invalid_argument for a description that could not stand in the registry:
// register_algorithm's rules.
void check_description(std::string_view caller, const Algorithm& algorithm, bool name_taken) {
  const std::string name = std::string(caller) + "(\"" + std::string(algorithm.name) + "\")";
  if (!valid_name(algorithm.name))
    throw std::invalid_argument(name + ": a name is lowercase letters, digits, '-', '_' and '.', and does not end in " +
                                std::string(outlier_filter_suffix));
  if (name_taken) throw std::invalid_argument(name + ": the name is taken");
  if (!algorithm.reconstruct) throw std::invalid_argument(name + ": no reconstruct function");
  for (const Parameter& parameter : algorithm.parameters)
    if (!(parameter.minimum <= parameter.default_value && parameter.default_value <= parameter.maximum))
      throw std::invalid_argument(name + ": parameter " + std::string(parameter.name) +
                                  "'s default is outside its range");
}

// The session algorithms (add_session_algorithm) and the texts their views point into: a
// deque does not move its elements, so the addresses handed out stay valid.
struct Session {
  std::mutex mutex;
  std::deque<std::string> texts;
  std::deque<Algorithm> algorithms;
};

Session& session_table() {
  static Session session;
  return session;
}

}  // namespace

std::span<const Algorithm> registry() {
  Table& all = table();
  all.read = true;
  return all.algorithms;
}

std::span<const Algorithm> registered_algorithms() { return registry().subspan(table().built_in_count); }

void register_algorithm(Algorithm algorithm) {
  Table& all = table();
  const bool taken = std::ranges::find(all.algorithms, algorithm.name, &Algorithm::name) != all.algorithms.end();
  check_description("register_algorithm", algorithm, taken);
  if (all.read)
    throw std::logic_error("register_algorithm(\"" + std::string(algorithm.name) +
                           "\"): the registry has been read already; register before main (Registration)");
  all.algorithms.push_back(std::move(algorithm));
}

const Algorithm& add_session_algorithm(Algorithm algorithm) {
  const auto all = registry();
  Session& session = session_table();
  const std::scoped_lock lock(session.mutex);
  const bool taken = std::ranges::find(all, algorithm.name, &Algorithm::name) != all.end() ||
                     std::ranges::find(session.algorithms, algorithm.name, &Algorithm::name) != session.algorithms.end();
  check_description("add_session_algorithm", algorithm, taken);
  // The views are re-pointed at copies that live as long as the program.
  const auto kept = [&session](std::string_view& text) { text = session.texts.emplace_back(text); };
  kept(algorithm.name), kept(algorithm.title), kept(algorithm.reference), kept(algorithm.category);
  kept(algorithm.capabilities.time_complexity), kept(algorithm.condition.statement);
  for (Parameter& parameter : algorithm.parameters) kept(parameter.name), kept(parameter.meaning);
  return session.algorithms.emplace_back(std::move(algorithm));
}

std::vector<const Algorithm*> session_algorithms() {
  Session& session = session_table();
  const std::scoped_lock lock(session.mutex);
  std::vector<const Algorithm*> added;
  for (const Algorithm& algorithm : session.algorithms) added.push_back(&algorithm);
  return added;
}

Registration::Registration(Algorithm algorithm) { register_algorithm(std::move(algorithm)); }

const Algorithm* find_algorithm(std::string_view name) {
  const auto found = [](std::string_view wanted) -> const Algorithm* {
    const auto all = registry();
    if (const auto it = std::ranges::find(all, wanted, &Algorithm::name); it != all.end()) return &*it;
    Session& session = session_table();
    const std::scoped_lock lock(session.mutex);
    const auto added = std::ranges::find(session.algorithms, wanted, &Algorithm::name);
    return added != session.algorithms.end() ? &*added : nullptr;
  };
  if (const Algorithm* algorithm = found(name)) return algorithm;
  if (!name.ends_with(outlier_filter_suffix)) return nullptr;
  const Algorithm* base = found(name.substr(0, name.size() - outlier_filter_suffix.size()));
  if (!base) return nullptr;
  // Built on first use and kept, with its name and title, for the program's lifetime (a
  // deque does not move its elements), as the registry's own entries are.
  static std::mutex mutex;
  static std::deque<std::string> texts;
  static std::deque<Algorithm> filtered;
  const std::scoped_lock lock(mutex);
  const auto made = std::ranges::find(filtered, name, &Algorithm::name);
  if (made != filtered.end()) return &*made;
  Algorithm algorithm = with_outlier_filter(*base);
  algorithm.name = texts.emplace_back(name);
  algorithm.title = texts.emplace_back(std::string(base->title) + " + outlier filter");
  return &filtered.emplace_back(std::move(algorithm));
}

std::vector<Edge> edges_in_lexicographic_order(std::span<const Point> points,
                                               const std::function<std::vector<Edge>(std::span<const Point>)>& edges_of) {
  std::vector<std::size_t> by_place(points.size());
  std::iota(by_place.begin(), by_place.end(), std::size_t{0});
  std::ranges::stable_sort(by_place, [&](std::size_t a, std::size_t b) { return points[a] < points[b]; });
  std::vector<Point> sorted;
  sorted.reserve(points.size());
  for (const std::size_t i : by_place) sorted.push_back(points[i]);
  std::vector<Edge> edges = edges_of(sorted);
  for (Edge& edge : edges) {
    if (std::max(edge.first, edge.second) >= sorted.size())
      throw std::logic_error("an algorithm returned an edge to point " + std::to_string(std::max(edge.first, edge.second)) +
                             " of " + std::to_string(sorted.size()));
    edge = {by_place[edge.first], by_place[edge.second]};
  }
  return geometry::canonical_edges(std::move(edges));
}

Reconstruction reconstruct(const Algorithm& algorithm, std::span<const Point> points, const Parameter_values& values) {
  values.check(algorithm.parameters, algorithm.name);
  const geometry::PointSet distinct(std::vector<Point>(points.begin(), points.end()));
  Reconstruction result = algorithm.reconstruct(distinct.points(), values);
  if (result.points.empty())  // the edges index the distinct points: name the input's
    for (Edge& edge : result.edges) edge = {distinct.input_index(edge.first), distinct.input_index(edge.second)};
  result.edges = geometry::canonical_edges(std::move(result.edges));
  return result;
}

}  // namespace curvebench::algorithms
