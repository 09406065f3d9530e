#include "geometry/sampling/sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "geometry/lfs/curve_search.h"
#include "geometry/sampling/seeded_random.h"

namespace curvebench::geometry {
namespace {

constexpr double safe_margin = 1e-3;  // the measure searches its own grid: stay clear of the target
constexpr int bisection_steps = 60;
constexpr std::size_t no_index = std::numeric_limits<std::size_t>::max();

double piece_count(const Curve_component& component) { return static_cast<double>(component.piece_count()); }

double distance(const Point& p, const Point& q) { return std::sqrt(CGAL::squared_distance(p, q)); }

// Appends the points at `parameters` (in order along the component) with their chain.
void append(Sample& sample, const Local_feature_size& lfs, std::size_t c, const std::vector<double>& parameters) {
  const Curve_component& component = lfs.curve().components[c];
  const std::size_t first = sample.size();
  for (double s : parameters) {
    if (component.closed()) s = std::fmod(s, piece_count(component));
    const double local = lfs.at(c, s);
    if (local < sample.minimum_lfs) sample.floored.push_back(sample.size());
    if (sample.size() > first) sample.edges.emplace_back(sample.size() - 1, sample.size());
    sample.points.push_back(component.point(s));
    sample.lfs.push_back(local);
    sample.locations.push_back({c, s});
    sample.labels.push_back(Sample_label::curve_point);
  }
  if (component.closed() && sample.size() - first >= 3) sample.edges.emplace_back(sample.size() - 1, first);
}

// Samples every walk keeps: the corners, and the ends of an open component (or the start
// of a closed one without corners).
std::vector<double> anchors(const Curve_component& component) {
  std::vector<double> fixed = component.corners();
  if (!component.closed()) {
    if (fixed.empty() || fixed.front() != 0) fixed.insert(fixed.begin(), 0.0);
    if (fixed.back() != piece_count(component)) fixed.push_back(piece_count(component));
  } else if (fixed.empty()) {
    fixed.push_back(0);
  }
  return fixed;
}

// A walk's admission test for a candidate v, given the last sample u (set by start(u)),
// after the grid points passed since u (each given to pass(v)).
class Step {
 public:
  Step(const Local_feature_size& lfs, std::size_t c, double target, double minimum_lfs)
      : lfs_(lfs), c_(c), target_(target), minimum_lfs_(minimum_lfs) {}

 protected:
  Point point(double s) const { return lfs_.curve().components[c_].point(s); }
  double lfs_at(double s) const { return lfs_.at(c_, s); }

  const Local_feature_size& lfs_;
  std::size_t c_;
  double target_, minimum_lfs_;
  Point from_;
};

// The survey's epsilon: v is within epsilon lfs(v) of u.
class Epsilon_step : Step {
 public:
  static constexpr int grid_subdivisions = 1;  // the survey's candidates: the dense lfs sample

  using Step::Step;
  void start(double u) { from_ = point(u); }
  bool admits(double v) const { return relative_distance(distance(from_, point(v)), lfs_at(v), minimum_lfs_) < target_; }
  void pass(double) {}
};

// HNN-Crust's rho: half the chord against the reach of the interval walked so far.
class Rho_step : Step {
 public:
  static constexpr int grid_subdivisions = 1;

  using Step::Step;
  void start(double u) {
    from_ = point(u);
    reach_ = lfs_at(u);
  }
  bool admits(double v) const {
    return relative_distance(distance(from_, point(v)) / 2, std::min(reach_, lfs_at(v)), minimum_lfs_) < target_;
  }
  void pass(double v) { reach_ = std::min(reach_, lfs_at(v)); }

 private:
  double reach_ = 0;
};

// The definition of epsilon itself: every curve point passed since u is within the
// target of u or of v. Checked on a grid of 8 steps per gap of the dense lfs sample, each
// grid point p standing for the curve within one step h of it: as distances and lfs (a
// distance to the medial points) are 1-Lipschitz, min(|p u|, |p v|) + h < epsilon
// (lfs(p) - h) covers them all.
//
// Incremental, with the same answers as testing every passed point against v: a point
// covered by u is covered whatever v is (the test is monotone in the distance), so only
// the others are kept; each of those gets a distance budget (a distance to v below which
// its test holds) and a slack against a reference point r (a recent v): while |r v| is
// within the slack, |p v| <= |p r| + |r v| is within the budget (with margins far above
// the rounding of both sides) and the test needs no evaluation. A walk then evaluates a
// few points per candidate instead of all of them.
class Coverage_step : Step {
 public:
  static constexpr int grid_subdivisions = 8;

  using Step::Step;
  void start(double u) {
    from_ = last_ = point(u);
    open_.clear();
    has_reference_ = false;
    smallest_slack_ = infinity;
    last_failed_ = no_point;
  }
  bool admits(double v) {
    if (open_.empty()) return true;
    const Point to = point(v);
    const double moved = distance(reference_, to);
    if (moved <= smallest_slack_) return true;
    if (last_failed_ < open_.size() && !(moved <= open_[last_failed_].slack) && !holds(open_[last_failed_], to))
      return false;
    std::size_t evaluated = 0;
    for (std::size_t i = 0; i < open_.size(); ++i) {
      if (moved <= open_[i].slack) continue;
      ++evaluated;
      if (!holds(open_[i], to)) {
        last_failed_ = i;
        return false;
      }
    }
    if (evaluated > 2 + open_.size() / 16) {  // the reference is stale: move it here
      reference_ = to;
      smallest_slack_ = infinity;
      for (Open& p : open_) smallest_slack_ = std::min(smallest_slack_, p.slack = slack(p, distance(p.point, to)));
    }
    return true;
  }
  void pass(double v) {
    const Point p = point(v);
    // The arc between grid points is at most 1.001 times their chord (they are far
    // closer than the radius of curvature).
    const double step = 1.001 * distance(p, last_), local = lfs_at(v);
    last_ = p;
    const double from = distance(p, from_);
    if (relative_distance(from + step, local - step, minimum_lfs_) < target_) return;  // covered by u
    Open open{p, from, step, local, -infinity, -infinity};
    const double budget = (target_ * std::max(local - step, minimum_lfs_) - step) * (1 - 1e-9);
    if (budget > 0 && holds(open, budget)) open.budget = budget;
    if (!has_reference_) reference_ = p, has_reference_ = true;
    open.slack = slack(open, distance(p, reference_));
    smallest_slack_ = std::min(smallest_slack_, open.slack);
    open_.push_back(open);
  }

 private:
  static constexpr std::size_t no_point = static_cast<std::size_t>(-1);
  static constexpr double infinity = std::numeric_limits<double>::infinity();

  struct Open {
    Point point;
    double from, step, lfs;
    double budget;  // a distance to v within which the test holds; -infinity if none is known
    double slack;   // |r v| within which |p v| is within the budget
  };
  // The test itself, with |p v| = to_distance.
  bool holds(const Open& p, double to_distance) const {
    return relative_distance(std::min(p.from, to_distance) + p.step, p.lfs - p.step, minimum_lfs_) < target_;
  }
  bool holds(const Open& p, const Point& to) const { return holds(p, distance(p.point, to)); }
  // Computed distances are within 4e-16 relative of the true ones, so if |r v| <= slack,
  // the computed |p v| <= (|p r| + |r v|) (1 + 3e-15) < budget; the absolute term covers
  // underflow.
  static double slack(const Open& p, double reference_distance) {
    return p.budget * (1 - 1e-13) - reference_distance - 1e-150;
  }

  Point last_;
  std::vector<Open> open_;  // the points passed since u that u does not cover
  Point reference_;
  bool has_reference_ = false;
  double smallest_slack_ = infinity;
  std::size_t last_failed_ = no_point;
};

// The greedy walk from `begin` to `end` over the dense lfs sample: appends the samples
// strictly between them.
template <class Step>
void walk(const Local_feature_size& lfs, std::size_t c, double begin, double end, Step& step, std::vector<double>& out) {
  const std::vector<double> candidates = lfs.grid(c, begin, end, Step::grid_subdivisions);
  double u = begin;
  step.start(u);
  for (std::size_t j = 1; j < candidates.size();) {
    if (step.admits(candidates[j])) {
      step.pass(candidates[j++]);
      continue;
    }
    double low = std::max(candidates[j - 1], u), high = candidates[j];
    for (int i = 0; i < bisection_steps; ++i) {
      const double middle = low + (high - low) / 2;
      if (middle <= low || middle >= high) break;
      (step.admits(middle) ? low : high) = middle;
    }
    u = low > u ? low : high;  // always move on, even if the boundary is below double resolution
    out.push_back(u);
    step.start(u);
    if (u >= candidates[j]) ++j;
  }
}

// The walk through each component, from anchor to anchor; returns the parameters in order.
template <class Make_step>
std::vector<std::vector<double>> walk_curve(const Local_feature_size& lfs, Make_step make_step) {
  std::vector<std::vector<double>> all;
  for (std::size_t c = 0; c < lfs.curve().components.size(); ++c) {
    const Curve_component& component = lfs.curve().components[c];
    const std::vector<double> fixed = anchors(component);
    auto step = make_step(c);
    auto& parameters = all.emplace_back();
    const std::size_t spans = component.closed() ? fixed.size() : fixed.size() - 1;
    for (std::size_t k = 0; k < spans; ++k) {
      parameters.push_back(fixed[k]);
      walk(lfs, c, fixed[k], k + 1 < fixed.size() ? fixed[k + 1] : fixed[0] + piece_count(component), step, parameters);
    }
    if (!component.closed()) parameters.push_back(fixed.back());
  }
  return all;
}

Sample assemble(const Local_feature_size& lfs, const std::vector<std::vector<double>>& parameters, double minimum_lfs) {
  Sample sample;
  sample.minimum_lfs = minimum_lfs;
  for (std::size_t c = 0; c < parameters.size(); ++c) append(sample, lfs, c, parameters[c]);
  return sample;
}

void check_walk_arguments(const char* name, double target, double minimum_lfs) {
  if (!(target > 0 && std::isfinite(target)) || !(minimum_lfs > 0 && std::isfinite(minimum_lfs)))
    throw std::invalid_argument(std::string(name) + ": the target and minimum_lfs must be positive and finite");
}

// The worst-covered point of [u, v] (its distance to the nearer end over its lfs), searched
// along the curve (curve_search.h).
Curve_maximum interval_epsilon(const Local_feature_size& lfs, std::size_t c, double u, double v, double minimum_lfs) {
  const Curve_component& component = lfs.curve().components[c];
  const Point pu = component.point(u), pv = component.point(v);
  return maximize_along(lfs, c, u, v, [&](double s) {
    const Point p = component.point(s);
    return relative_distance(std::min(distance(p, pu), distance(p, pv)), lfs.at(c, s), minimum_lfs);
  });
}

// Splits [u, v] at its worst-covered point until each part is covered within the target;
// appends u and the split points.
void cover(const Local_feature_size& lfs, std::size_t c, double u, double v, double target, double minimum_lfs,
           std::vector<double>& out) {
  const Curve_maximum worst = interval_epsilon(lfs, c, u, v, minimum_lfs);
  if (worst.value <= target * (1 - safe_margin) || !(worst.parameter > u && worst.parameter < v)) {
    out.push_back(u);
    return;
  }
  cover(lfs, c, u, worst.parameter, target, minimum_lfs, out);
  cover(lfs, c, worst.parameter, v, target, minimum_lfs, out);
}

// Each walked component's intervals between adjacent samples, the closing one of a closed
// component included, given to `split(c, u, v, out)`, which appends u and its split points;
// an open component keeps its last sample.
template <class Split>
std::vector<std::vector<double>> split_intervals(const Local_feature_size& lfs,
                                                 const std::vector<std::vector<double>>& walked, Split split) {
  std::vector<std::vector<double>> result;
  for (std::size_t c = 0; c < walked.size(); ++c) {
    const Curve_component& component = lfs.curve().components[c];
    const std::vector<double>& s = walked[c];
    auto& parameters = result.emplace_back();
    for (std::size_t i = 0; i + 1 < s.size(); ++i) split(c, s[i], s[i + 1], parameters);
    if (component.closed())
      split(c, s.back(), s.front() + piece_count(component), parameters);
    else
      parameters.push_back(s.back());
  }
  return result;
}

std::vector<std::vector<double>> safe_epsilon_parameters(const Local_feature_size& lfs, double epsilon,
                                                         double minimum_lfs) {
  check_walk_arguments("safe epsilon sampling", epsilon, minimum_lfs);
  const auto walked = walk_curve(
      lfs, [&](std::size_t c) { return Coverage_step(lfs, c, epsilon * (1 - safe_margin), minimum_lfs); });
  return split_intervals(lfs, walked, [&](std::size_t c, double u, double v, std::vector<double>& out) {
    cover(lfs, c, u, v, epsilon, minimum_lfs, out);
  });
}

// The interval [u, v]'s rho, as certify measures it: half its chord against its reach (the
// least lfs over it, floored), searched along the curve (curve_search.h).
double interval_rho(const Local_feature_size& lfs, std::size_t c, double u, double v, double minimum_lfs) {
  const Curve_component& component = lfs.curve().components[c];
  const Curve_maximum lowest =
      maximize_along(lfs, c, u, v, [&](double s) { return -std::max(lfs.at(c, s), minimum_lfs); });
  return relative_distance(distance(component.point(u), component.point(v)) / 2, -lowest.value, 0);
}

// Splits [u, v] in the middle (of its parameter) until each part's rho is within the
// target; appends u and the split points.
void cover_rho(const Local_feature_size& lfs, std::size_t c, double u, double v, double target, double minimum_lfs,
               std::vector<double>& out) {
  const double middle = u + (v - u) / 2;
  if (interval_rho(lfs, c, u, v, minimum_lfs) <= target * (1 - safe_margin) || !(middle > u && middle < v)) {
    out.push_back(u);
    return;
  }
  cover_rho(lfs, c, u, middle, target, minimum_lfs, out);
  cover_rho(lfs, c, middle, v, target, minimum_lfs, out);
}

// The worst epsilon of the intervals between adjacent samples.
double worst_epsilon(const Local_feature_size& lfs, std::size_t c, const std::vector<double>& parameters,
                     double minimum_lfs) {
  const Curve_component& component = lfs.curve().components[c];
  double worst = 0;
  const std::size_t intervals = component.closed() ? parameters.size() : parameters.size() - 1;
  for (std::size_t i = 0; i < intervals; ++i) {
    const double u = parameters[i], v = i + 1 < parameters.size() ? parameters[i + 1] : parameters[0] + piece_count(component);
    worst = std::max(worst, interval_epsilon(lfs, c, u, v, minimum_lfs).value);
  }
  return worst;
}

// The largest ratio of adjacent chords at a point of two chords.
double worst_uniformity(const Curve_component& component, const std::vector<double>& parameters) {
  std::vector<double> chord;
  const std::size_t n = parameters.size(), chords = component.closed() ? n : n - 1;
  for (std::size_t e = 0; e < chords; ++e) chord.push_back(distance(component.point(parameters[e]), component.point(parameters[(e + 1) % n])));
  double worst = 1;
  for (std::size_t i = component.closed() ? 0 : 1; i < (component.closed() ? n : n - 1); ++i) {
    const double a = chord[i > 0 ? i - 1 : chords - 1], b = chord[i];
    worst = std::max(worst, std::min(a, b) > 0 ? std::max(a, b) / std::min(a, b) : std::numeric_limits<double>::infinity());
  }
  return worst;
}

// One smooth component sampled by a size field: samples where the integral of
// 1 / (scale h) along the arc length passes equal steps, h(a) = min over b of
// lfs(b) + slope |a - b| (the envelope of lfs of that slope, on the dense lfs grid). The
// spacing follows scale h, which changes by at most slope x scale over one spacing, so
// adjacent chords differ by about that factor (lfs itself is 1-Lipschitz: slope 1 is lfs).
std::vector<double> size_field_samples(const Local_feature_size& lfs, std::size_t c, double scale, double slope,
                                       double minimum_lfs) {
  const Curve_component& component = lfs.curve().components[c];
  const bool closed = component.closed();
  const std::vector<double> grid = lfs.grid(c, 0, piece_count(component), 8);
  const std::size_t m = grid.size();
  std::vector<double> arc(m), h(m);
  for (std::size_t k = 0; k < m; ++k) arc[k] = k + 1 < m ? component.arc_length(grid[k]) : component.length();
  for (std::size_t k = 0; k < m; ++k) h[k] = std::max(lfs.at(c, std::min(grid[k], piece_count(component))), minimum_lfs);
  // The envelope by sweeps forward and back (twice round a closed component, for the wrap).
  for (int round = 0; round < (closed ? 2 : 1); ++round) {
    for (std::size_t k = 1; k < m; ++k) h[k] = std::min(h[k], h[k - 1] + slope * (arc[k] - arc[k - 1]));
    if (closed) h[0] = std::min(h[0], h[m - 1]);
    for (std::size_t k = m - 1; k > 0; --k) h[k - 1] = std::min(h[k - 1], h[k] + slope * (arc[k] - arc[k - 1]));
    if (closed) h[m - 1] = std::min(h[m - 1], h[0]);
  }
  std::vector<double> integral(m, 0);  // of 1 / (scale h), by trapezoids
  for (std::size_t k = 1; k < m; ++k)
    integral[k] = integral[k - 1] + (arc[k] - arc[k - 1]) * (1 / h[k] + 1 / h[k - 1]) / (2 * scale);
  const double total = integral.back();
  const std::size_t steps = std::max<std::size_t>(closed ? 3 : 1, static_cast<std::size_t>(std::ceil(total)));
  std::vector<double> parameters;
  std::size_t k = 1;
  for (std::size_t j = 0; j < (closed ? steps : steps + 1); ++j) {
    const double target = total * static_cast<double>(j) / static_cast<double>(steps);
    while (k + 1 < m && integral[k] < target) ++k;
    const double t = integral[k] > integral[k - 1] ? std::clamp((target - integral[k - 1]) / (integral[k] - integral[k - 1]), 0.0, 1.0) : 0;
    parameters.push_back(j == 0 ? 0.0 : j == steps ? piece_count(component) : grid[k - 1] + t * (grid[k] - grid[k - 1]));
  }
  return parameters;
}

// The sampling of one smooth component by a size field whose scale is searched (by
// bisection) for the sparsest sampling of epsilon at most `epsilon` and, with `slope`
// halved while needed, local uniformity below `uniformity`.
std::vector<double> graded_samples(const Local_feature_size& lfs, std::size_t c, double epsilon, double uniformity,
                                   double minimum_lfs) {
  const Curve_component& component = lfs.curve().components[c];
  for (double slope = 1; slope > 1e-3; slope /= 2) {
    // A chord of scale x lfs has its middle about scale / 2 lfs from both ends: start there.
    double low = 0, high = 4 * epsilon;
    std::vector<double> best;
    for (int step = 0; step < 12; ++step) {
      const double scale = best.empty() && step == 0 ? 2 * epsilon : low + (high - low) / 2;
      std::vector<double> parameters = size_field_samples(lfs, c, scale, slope, minimum_lfs);
      if (worst_epsilon(lfs, c, parameters, minimum_lfs) <= epsilon * (1 - safe_margin)) {
        low = scale;
        best = std::move(parameters);
      } else {
        high = scale;
      }
    }
    if (best.empty()) best = size_field_samples(lfs, c, low > 0 ? low : epsilon / 8, slope, minimum_lfs);
    if (worst_uniformity(component, best) < uniformity * (1 - safe_margin) &&
        worst_epsilon(lfs, c, best, minimum_lfs) <= epsilon * (1 - safe_margin))
      return best;
  }
  throw std::invalid_argument("graded epsilon sampling: no sampling meets both bounds");
}

// n points along one component at equal arc-length steps (both ends if it is open).
std::vector<double> equal_steps(const Curve_component& component, std::size_t k) {
  std::vector<double> parameters;
  const double steps = static_cast<double>(component.closed() ? k : k - 1);
  for (std::size_t j = 0; j < k; ++j)
    parameters.push_back(component.parameter_at_arc_length(component.length() * static_cast<double>(j) / steps));
  return parameters;
}

Sample equal_step_sample(const Local_feature_size& lfs, const std::vector<std::size_t>& counts) {
  std::vector<std::vector<double>> parameters;
  for (std::size_t c = 0; c < counts.size(); ++c) parameters.push_back(equal_steps(lfs.curve().components[c], counts[c]));
  return assemble(lfs, parameters, 0);
}

std::size_t minimum_points(const Curve_component& component) { return component.closed() ? 1 : 2; }

}  // namespace

double default_minimum_lfs(const Local_feature_size& lfs) { return 1e-3 * lfs.bounding_box_diagonal(); }

Sample epsilon_sampling(const Local_feature_size& lfs, double epsilon, double minimum_lfs) {
  check_walk_arguments("epsilon sampling", epsilon, minimum_lfs);
  return assemble(lfs, walk_curve(lfs, [&](std::size_t c) { return Epsilon_step(lfs, c, epsilon, minimum_lfs); }),
                  minimum_lfs);
}

Sample safe_epsilon_sampling(const Local_feature_size& lfs, double epsilon, double minimum_lfs) {
  return assemble(lfs, safe_epsilon_parameters(lfs, epsilon, minimum_lfs), minimum_lfs);
}

Sample graded_epsilon_sampling(const Local_feature_size& lfs, double epsilon, double uniformity, double minimum_lfs) {
  check_walk_arguments("graded epsilon sampling", epsilon, minimum_lfs);
  if (!(uniformity > 1 && std::isfinite(uniformity)))
    throw std::invalid_argument("graded epsilon sampling: the uniformity bound must be finite and above 1");
  std::vector<std::vector<double>> parameters;
  for (std::size_t c = 0; c < lfs.curve().components.size(); ++c) {
    if (!lfs.curve().components[c].corners().empty())
      throw std::invalid_argument("graded epsilon sampling: smooth curves only (component " + std::to_string(c) +
                                  " has a corner)");
    parameters.push_back(graded_samples(lfs, c, epsilon, uniformity, minimum_lfs));
  }
  return assemble(lfs, parameters, minimum_lfs);
}

Sample rho_sampling(const Local_feature_size& lfs, double rho, double minimum_lfs) {
  check_walk_arguments("rho sampling", rho, minimum_lfs);
  return assemble(lfs, walk_curve(lfs, [&](std::size_t c) { return Rho_step(lfs, c, rho, minimum_lfs); }), minimum_lfs);
}

Sample safe_rho_sampling(const Local_feature_size& lfs, double rho, double minimum_lfs) {
  check_walk_arguments("safe rho sampling", rho, minimum_lfs);
  const auto walked =
      walk_curve(lfs, [&](std::size_t c) { return Rho_step(lfs, c, rho * (1 - safe_margin), minimum_lfs); });
  const auto covered = split_intervals(lfs, walked, [&](std::size_t c, double u, double v, std::vector<double>& out) {
    cover_rho(lfs, c, u, v, rho, minimum_lfs, out);
  });
  return assemble(lfs, covered, minimum_lfs);
}

Sample with_crossing_samples(const Local_feature_size& lfs, Sample sample) {
  // A crossing is the sharp point that appears once per branch through it.
  struct Crossing {
    Point point;
    std::vector<Curve_location> branches;
    std::size_t index = no_index;  // its point in the new sample, once made
  };
  std::vector<Crossing> crossings;
  for (const Sharp_point& sharp : lfs.sharp_points()) {
    if (sharp.kind != Sharp_point::Kind::crossing) continue;
    const auto same = std::ranges::find(crossings, sharp.point, &Crossing::point);
    if (same == crossings.end())
      crossings.push_back({sharp.point, {sharp.location}});
    else
      same->branches.push_back(sharp.location);
  }
  std::erase_if(crossings, [](const Crossing& c) { return c.branches.size() < 2; });
  if (crossings.empty()) return sample;

  // Per component, its samples and its crossing branches in order along it (an entry is a
  // sample's index, or a crossing's as no_index - 1 - crossing).
  const std::size_t components = lfs.curve().components.size();
  std::vector<std::vector<std::pair<double, std::size_t>>> along(components);
  for (std::size_t i = 0; i < sample.size(); ++i)
    if (sample.labels[i] == Sample_label::curve_point)
      along[sample.locations[i].component].emplace_back(sample.locations[i].parameter, i);
  for (std::size_t x = 0; x < crossings.size(); ++x)
    for (const Curve_location& branch : crossings[x].branches) {
      auto& entries = along[branch.component];
      const bool sampled = std::ranges::any_of(entries, [&](const auto& e) { return e.first == branch.parameter; });
      if (!sampled) entries.emplace_back(branch.parameter, no_index - 1 - x);
    }

  Sample result;
  result.minimum_lfs = sample.minimum_lfs;
  const auto add = [&](const Point& p, double local, const Curve_location& location) {
    if (local < result.minimum_lfs) result.floored.push_back(result.size());
    result.points.push_back(p);
    result.lfs.push_back(local);
    result.locations.push_back(location);
    result.labels.push_back(Sample_label::curve_point);
    return result.size() - 1;
  };
  for (std::size_t c = 0; c < components; ++c) {
    auto& entries = along[c];
    std::ranges::sort(entries);
    std::vector<std::size_t> chain;
    for (const auto& [parameter, entry] : entries) {
      if (entry < sample.size()) {
        chain.push_back(add(sample.points[entry], sample.lfs[entry], sample.locations[entry]));
        continue;
      }
      Crossing& crossing = crossings[no_index - 1 - entry];
      if (crossing.index == no_index) crossing.index = add(crossing.point, 0, {c, parameter});
      chain.push_back(crossing.index);
    }
    for (std::size_t i = 0; i + 1 < chain.size(); ++i) result.edges.emplace_back(chain[i], chain[i + 1]);
    if (lfs.curve().components[c].closed() && chain.size() >= 3) result.edges.emplace_back(chain.back(), chain.front());
  }
  return result;
}

Sample uniform_sampling(const Local_feature_size& lfs, std::size_t n) {
  const auto& components = lfs.curve().components;
  std::vector<std::size_t> counts;
  for (const Curve_component& component : components) counts.push_back(minimum_points(component));
  const std::size_t fixed = std::accumulate(counts.begin(), counts.end(), std::size_t{0});
  if (n < fixed || (components.empty() && n > 0)) throw std::invalid_argument("uniform sampling: too few points for the curve's components");
  // Largest remainders: the spare points go by length, ties to the earlier component.
  const double spare = static_cast<double>(n - fixed), total = lfs.curve().length();
  std::vector<double> remainders;
  std::size_t given = fixed;
  for (std::size_t c = 0; c < components.size(); ++c) {
    const double share = total > 0 ? spare * components[c].length() / total : 0;
    counts[c] += static_cast<std::size_t>(share);
    given += static_cast<std::size_t>(share);
    remainders.push_back(share - std::floor(share));
  }
  std::vector<std::size_t> order(components.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return remainders[a] > remainders[b]; });
  for (std::size_t k = 0; given < n; ++k, ++given) ++counts[order[k % order.size()]];
  return equal_step_sample(lfs, counts);
}

Sample uniform_sampling_with_spacing(const Local_feature_size& lfs, double spacing) {
  if (!(spacing > 0 && std::isfinite(spacing)))
    throw std::invalid_argument("uniform sampling: the spacing must be positive and finite");
  std::vector<std::size_t> counts;
  for (const Curve_component& component : lfs.curve().components) {
    const auto steps = static_cast<std::size_t>(std::ceil(component.length() / spacing));
    counts.push_back(std::max(component.closed() ? steps : steps + 1, minimum_points(component)));
  }
  return equal_step_sample(lfs, counts);
}

Sample random_sampling(const Local_feature_size& lfs, std::size_t n, std::uint64_t seed) {
  const auto& components = lfs.curve().components;
  std::vector<double> cumulative{0};
  for (const Curve_component& component : components) cumulative.push_back(cumulative.back() + component.length());
  std::vector<std::vector<double>> lengths(components.size());
  Seeded_random random(seed);
  for (std::size_t i = 0; i < n && !components.empty(); ++i) {
    const double at = random.uniform() * cumulative.back();
    const std::size_t c = std::min<std::size_t>(
        std::upper_bound(cumulative.begin(), cumulative.end(), at) - cumulative.begin() - 1, components.size() - 1);
    lengths[c].push_back(at - cumulative[c]);
  }
  std::vector<std::vector<double>> parameters(components.size());
  for (std::size_t c = 0; c < components.size(); ++c) {
    std::sort(lengths[c].begin(), lengths[c].end());
    for (const double length : lengths[c]) parameters[c].push_back(components[c].parameter_at_arc_length(length));
  }
  return assemble(lfs, parameters, 0);
}

Sample sampling_at(const Local_feature_size& lfs, const std::vector<std::vector<double>>& parameters, double minimum_lfs) {
  if (parameters.size() > lfs.curve().components.size())
    throw std::invalid_argument("sampling_at: more parameter lists than the curve's components");
  return assemble(lfs, parameters, minimum_lfs);
}

}  // namespace curvebench::geometry
