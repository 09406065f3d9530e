#include "certify/tightness_search.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <stdexcept>

#include "algorithms/registry.h"
#include "certify/sampling_measure.h"
#include "geometry/curves/curve_spec.h"
#include "geometry/lfs/local_feature_size.h"
#include "geometry/sampling/sampling.h"
#include "geometry/sampling/seeded_random.h"

namespace curvebench::certify {
namespace {

using geometry::Edge;
using geometry::Local_feature_size;
using geometry::Sample;
using Clock = std::chrono::steady_clock;

std::string decimal(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", value);
  return text;
}

// A random smooth closed curve of the search's families, by its spec.
std::string random_curve(geometry::Seeded_random& random, std::uint64_t seed, bool several) {
  const double pick = random.uniform();
  const std::string seeded = "seed=" + std::to_string(seed);
  if (pick < 0.2) return "star:" + seeded + ",angle=" + std::to_string(30 + 30 * (seed % 3)) + ",rounding=0.05";
  std::string spec = "fourier:" + seeded + ",harmonics=" + std::to_string(1 + seed % 8) +
                     ",amplitude=" + decimal(random.uniform(0.2, 0.6)) + ",decay=" + decimal(random.uniform(0.5, 2));
  if (several && pick < 0.35) spec += ",components=2";
  return spec;
}

// One curve's search state: its lfs, the theorem, and the evaluation of a sampling.
class Curve_search {
 public:
  Curve_search(const algorithms::Algorithm& algorithm, const Theorem& theorem, const Local_feature_size& lfs,
               std::size_t& evaluations)
      : algorithm_(algorithm), theorem_(theorem), lfs_(lfs), floor_(geometry::default_minimum_lfs(lfs)),
        evaluations_(evaluations) {}

  // A sampling and what the search knows of it.
  struct Candidate {
    Sample sample;
    double measured = INFINITY;
    Edge worst{0, 0};  // the interval (i, j) along the curve where the measure is attained
    bool fails = false;
    Reconstruction_check check = {};
  };

  Candidate at_level(double level) const {
    if (theorem_.measure == Measure::rho) return evaluate(geometry::safe_rho_sampling(lfs_, level, floor_));
    if (theorem_.uniformity_below)
      return evaluate(geometry::graded_epsilon_sampling(lfs_, level, *theorem_.uniformity_below, floor_));
    return evaluate(geometry::safe_epsilon_sampling(lfs_, level, floor_));
  }

  Candidate at_parameters(const std::vector<std::vector<double>>& parameters) const {
    return evaluate(geometry::sampling_at(lfs_, parameters, floor_));
  }

 private:
  // Fails: not reconstructed exactly although every hypothesis but the theorem's measure
  // holds (Connect2D's local uniformity, where the theorem bounds it).
  Candidate evaluate(Sample sample) const {
    ++evaluations_;
    Candidate c{.sample = std::move(sample)};
    if (theorem_.measure == Measure::rho) {
      const Rho_measure rho = measure_rho(lfs_, c.sample, 0);
      c.measured = rho.rho, c.worst = rho.edge;
    } else {
      const Epsilon_measure epsilon = measure_epsilon(lfs_, c.sample.points, 0);
      c.measured = epsilon.epsilon, c.worst = interval_at(c.sample, epsilon.where);
    }
    // A closed component with fewer than three samples has no polygon to reconstruct (and
    // no edge to measure rho on): too sparse to be a case. (The first rho search returned
    // two points of two components, rho 0 over no edges.)
    std::vector<std::size_t> per_component(lfs_.curve().components.size(), 0);
    for (const auto& location : c.sample.locations) ++per_component[location.component];
    if (std::ranges::any_of(per_component, [](std::size_t n) { return n < 3; })) return c;
    if (theorem_.uniformity_below &&
        !(measure_uniformity(c.sample.points, c.sample.edges).uniformity < *theorem_.uniformity_below))
      return c;
    c.check = check_reconstruction(algorithm_, c.sample);
    c.fails = !c.check.exact && std::isfinite(c.measured);
    return c;
  }

  // The ground-truth edge (i, j) whose interval along the curve holds `where`.
  static Edge interval_at(const Sample& sample, const geometry::Curve_location& where) {
    for (const Edge& e : sample.edges) {
      const auto [i, j] = e;
      const auto& a = sample.locations[i];
      const auto& b = sample.locations[j];
      if (a.component != where.component) continue;
      const bool wraps = b.parameter <= a.parameter;
      const double s = where.parameter;
      if (wraps ? (s >= a.parameter || s <= b.parameter) : (s >= a.parameter && s <= b.parameter)) return e;
    }
    return sample.edges.empty() ? Edge{0, 0} : sample.edges.front();
  }

  const algorithms::Algorithm& algorithm_;
  const Theorem& theorem_;
  const Local_feature_size& lfs_;
  double floor_;
  std::size_t& evaluations_;
};

// The sample parameters of each component, from a sample's locations (in order along each).
std::vector<std::vector<double>> parameters_of(const Sample& sample, std::size_t components) {
  std::vector<std::vector<double>> parameters(components);
  for (const auto& location : sample.locations) parameters[location.component].push_back(location.parameter);
  return parameters;
}

// Index of point i within its component's parameter list.
std::pair<std::size_t, std::size_t> component_index(const Sample& sample, std::size_t i) {
  std::size_t first = i;
  while (first > 0 && sample.locations[first - 1].component == sample.locations[i].component) --first;
  return {sample.locations[i].component, i - first};
}

// The parameter half-way along the interval of edge (i, j), forward from i (around the end
// of a closed component when j comes first).
double midpoint(const Sample& sample, const Local_feature_size& lfs, Edge e) {
  const auto& a = sample.locations[e.first];
  const auto& b = sample.locations[e.second];
  const double n = static_cast<double>(lfs.curve().components[a.component].piece_count());
  const double end = b.parameter > a.parameter ? b.parameter : b.parameter + n;
  return std::fmod((a.parameter + end) / 2, n);
}

}  // namespace

Reconstruction_check check_reconstruction(const algorithms::Algorithm& algorithm, const Sample& sample) {
  Reconstruction_check check;
  try {
    algorithms::Reconstruction result = algorithms::reconstruct(algorithm, sample.points);
    check.edges = std::move(result.edges);
    check.exact = result.points.empty() && check.edges == geometry::canonical_edges(sample.edges);
  } catch (const std::exception& error) {
    check.error = error.what();
  }
  return check;
}

Tightness_result search_tightness(const algorithms::Algorithm& algorithm, const Tightness_options& options) {
  const auto theorem = theorem_of(algorithm, options.measure);
  if (!theorem)
    throw std::invalid_argument(std::string(algorithm.name) + " has no proven " + std::string(measure_name(options.measure)) +
                                " bound to search below");
  Tightness_result result{.theorem = *theorem};
  const auto start = Clock::now();
  const auto out_of_time = [&] {
    return std::chrono::duration<double>(Clock::now() - start).count() >= options.seconds;
  };
  const bool several = algorithm.capabilities.multiple != algorithms::Support::no;
  geometry::Seeded_random random(options.seed);

  for (std::uint64_t index = 0; !out_of_time() && (options.max_curves == 0 || result.curves < options.max_curves); ++index) {
    const std::string spec = random_curve(random, (options.seed << 32) + index, several);
    std::optional<Local_feature_size> lfs;
    try {
      lfs.emplace(geometry::make_curve(spec));
    } catch (const std::invalid_argument&) {
      continue;  // a random curve that is not simple: the family refuses it
    }
    ++result.curves;
    Curve_search search(algorithm, *theorem, *lfs, result.evaluations);

    // 1. The sparsest level: up a ladder from the bound, then bisection.
    double passed = 0, failed = 0;
    Curve_search::Candidate best;
    for (double level = theorem->bound; level < 6 && !out_of_time(); level *= 1.4) {
      Curve_search::Candidate c;
      try {
        c = search.at_level(level);
      } catch (const std::invalid_argument&) {
        break;  // a level the sampler refuses (too sparse for this curve)
      }
      if (c.fails) {
        failed = level, best = std::move(c);
        break;
      }
      if (c.check.exact) result.largest_passed = std::max(result.largest_passed, c.measured);
      passed = level;
    }
    if (failed == 0) continue;
    ++result.failing_curves;
    for (int step = 0; step < 5 && passed > 0 && !out_of_time(); ++step) {
      const double middle = std::sqrt(passed * failed);
      Curve_search::Candidate c;
      try {
        c = search.at_level(middle);
      } catch (const std::invalid_argument&) {
        break;
      }
      if (c.fails) {
        failed = middle, best = std::move(c);
      } else {
        if (c.check.exact) result.largest_passed = std::max(result.largest_passed, c.measured);
        passed = middle;
      }
    }
    Tightness_case found{.curve = spec, .level = failed};
    // Steps 2 and 3 only where this curve's failure could beat the best found.
    if (!result.best || best.measured < 1.5 * result.best->measured) {
      const std::size_t components = lfs->curve().components.size();
      // 2. Densify where the measure is attained, while the case still fails.
      for (int tries = 0; tries < 200 && !out_of_time(); ++tries) {
        auto parameters = parameters_of(best.sample, components);
        auto& list = parameters[best.sample.locations[best.worst.first].component];
        list.push_back(midpoint(best.sample, *lfs, best.worst));
        std::sort(list.begin(), list.end());
        Curve_search::Candidate next = search.at_parameters(parameters);
        if (!next.fails || !(next.measured < best.measured)) break;
        best = std::move(next), ++found.added;
      }
      // 3. Move samples: the ends of the worst interval and of wrong edges first.
      for (std::size_t move = 0; move < options.moves && !out_of_time(); ++move) {
        const Sample& sample = best.sample;
        const std::vector<Edge> truth = geometry::canonical_edges(sample.edges);
        std::vector<std::size_t> wrong;  // ends of edges found but not true, and true but not found
        std::vector<Edge> differ;
        std::ranges::set_symmetric_difference(best.check.edges, truth, std::back_inserter(differ));
        for (const Edge& e : differ) wrong.insert(wrong.end(), {e.first, e.second});
        const double pick = random.uniform();
        const auto draw = [&](std::size_t n) { return std::min(n - 1, static_cast<std::size_t>(random.uniform() * n)); };
        const std::size_t i = pick < 0.5   ? (pick < 0.25 ? best.worst.first : best.worst.second)
                              : pick < 0.8 && !wrong.empty() ? wrong[draw(wrong.size())]
                                                             : draw(sample.size());
        auto parameters = parameters_of(sample, components);
        const auto [c, k] = component_index(sample, i);
        auto& list = parameters[c];
        if (list.size() < 4) continue;
        const double n = static_cast<double>(lfs->curve().components[c].piece_count());
        const double previous = k > 0 ? list[k - 1] : list.back() - n;
        const double next = k + 1 < list.size() ? list[k + 1] : list.front() + n;
        const double share = random.uniform(-0.45, 0.45);
        list[k] = std::fmod(list[k] + (share < 0 ? share * (list[k] - previous) : share * (next - list[k])) + n, n);
        std::sort(list.begin(), list.end());
        Curve_search::Candidate candidate = search.at_parameters(parameters);
        if (candidate.fails && candidate.measured <= best.measured) best = std::move(candidate), ++found.moved;
      }
    }
    if (!result.best || best.measured < result.best->measured) {
      found.sample = std::move(best.sample);
      found.measured = best.measured;
      found.reconstruction = std::move(best.check.edges);
      found.error = std::move(best.check.error);
      result.best = std::move(found);
    }
  }
  result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

}  // namespace curvebench::certify
