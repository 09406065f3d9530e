#include "bench/runner/hunt.h"

#include <nlohmann/json.hpp>
#include <rapidcheck.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "algorithms/registry.h"
#include "bench/runner/bench_input.h"
#include "bench/runner/external_algorithm.h"
#include "bench/runner/process_pool.h"
#include "bench/runner/results_table.h"
#include "certify/theorems.h"
#include "geometry/io/edge_io.h"
#include "geometry/io/point_io.h"
#include "geometry/point_set.h"

namespace curvebench::bench {
namespace {

using algorithms::Edge;
using geometry::Point;
using Clock = std::chrono::steady_clock;

// ---- Inputs -----------------------------------------------------------------------------

// 0, 1, -1, 2, -2, ...: a lattice coordinate that shrinks towards 0.
int zigzag(int k) { return k % 2 ? (k + 1) / 2 : -k / 2; }

// Scales that reach the huge, the tiny (subnormal) and the largest doubles; 0 first, so
// that a finding shrinks to plain integers.
const std::vector<int> exponents{0, 1, -1, 30, -30, 600, -600, 1000, -1000, 1019, -1070};

using Lattice = std::vector<std::pair<int, int>>;

// The degenerate families of the fuzz decoder, on the integer lattice: any points, points
// on one line, on one circle (the 12 lattice points of x^2 + y^2 = 25), on a 4 x 4 grid, and
// crowded in a 3 x 3 square (duplicates); and points on a fine lattice, in general position
// but for a rare draw. Each shrinks within its family.
rc::Gen<Lattice> lattice_sets() {
  const auto coordinate = rc::gen::map(rc::gen::inRange(0, 17), zigzag);
  const auto small = rc::gen::map(rc::gen::inRange(0, 7), zigzag);
  const auto any = rc::gen::container<Lattice>(rc::gen::pair(coordinate, coordinate));
  const auto line = rc::gen::map(
      rc::gen::tuple(rc::gen::pair(small, small), rc::gen::pair(small, small), rc::gen::container<std::vector<int>>(small)),
      [](const std::tuple<std::pair<int, int>, std::pair<int, int>, std::vector<int>>& drawn) {
        const auto& [origin, step, ks] = drawn;
        Lattice points;
        for (const int k : ks) points.emplace_back(origin.first + k * step.first, origin.second + k * step.second);
        return points;
      });
  static const Lattice circle{{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3}, {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
  const auto on_circle = rc::gen::map(rc::gen::container<std::vector<int>>(rc::gen::inRange(0, 12)), [](const std::vector<int>& ks) {
    Lattice points;
    for (const int k : ks) points.push_back(circle[k]);
    return points;
  });
  const auto grid = rc::gen::container<Lattice>(rc::gen::pair(rc::gen::inRange(0, 4), rc::gen::inRange(0, 4)));
  const auto crowded = rc::gen::container<Lattice>(rc::gen::pair(rc::gen::inRange(0, 3), rc::gen::inRange(0, 3)));
  // Fine coordinates: almost always in general position, where the laws are checked.
  const auto generic = rc::gen::container<Lattice>(rc::gen::pair(rc::gen::inRange(0, 1 << 20), rc::gen::inRange(0, 1 << 20)));
  return rc::gen::oneOf(any, line, on_circle, grid, crowded, generic, generic);
}

rc::Gen<std::vector<Point>> point_sets() {
  return rc::gen::map(
      rc::gen::tuple(lattice_sets(),
                     rc::gen::map(rc::gen::inRange(0, int(exponents.size())), [](int k) { return exponents[k]; }),
                     rc::gen::inRange(0, 4)),
      [](const std::tuple<std::vector<std::pair<int, int>>, int, int>& drawn) {
        const auto& [lattice, exponent, nudge] = drawn;
        std::vector<Point> points;
        for (const auto& [x, y] : lattice) points.emplace_back(std::ldexp(double(x), exponent), std::ldexp(double(y), exponent));
        if (nudge > 0 && !points.empty()) {  // one coordinate one ulp up: near-degenerate
          Point& p = points[std::size_t(nudge - 1) % points.size()];
          p = Point(std::nextafter(p.x(), HUGE_VAL), p.y());
        }
        return points;
      });
}

// A case: a point set, or a curve sampling named as a benchmark input (bench_input.h), whose
// points, ground truth and measured epsilon are made from the name when the case runs. The
// generator keeps the name only, so that drawing and shrinking cost nothing.
struct Hunt_case {
  std::vector<Point> points;
  std::string curve;  // empty for a point set
};

// Smooth closed curves (one Fourier curve, or two side by side for an algorithm that
// reconstructs several curves: Connect2D's theorem is about one) sampled near and beyond
// the algorithm's epsilon bound: at 0.95, 0.8 and 0.5 of it, where the theorem demands an
// exact reconstruction, and at 1.2 and 2 times it, where only a crash, a hang or invalid
// output is a defect. Without a bound, at epsilon 0.6 to 0.1. Each shrinks towards one
// curve of one harmonic, seed 0, and the coarsest sampling (the fewest points) under the
// bound.
// A theorem that also bounds local uniformity (Connect2D's) gets graded samplings that
// meet that bound too.
rc::Gen<std::string> curve_samplings(std::optional<double> bound, std::optional<double> uniformity, bool several_curves) {
  const std::vector<double> levels = bound ? std::vector<double>{0.95 * *bound, 0.8 * *bound, 0.5 * *bound, 1.2 * *bound, 2 * *bound}
                                           : std::vector<double>{0.6, 0.4, 0.2, 0.1};
  return rc::gen::map(rc::gen::tuple(rc::gen::inRange(1, several_curves ? 3 : 2), rc::gen::inRange(1, 9), rc::gen::inRange(0, 1 << 20),
                                     rc::gen::inRange(0, int(levels.size()))),
                      [levels, uniformity](const std::tuple<int, int, int, int>& drawn) {
                        const auto& [components, harmonics, seed, level] = drawn;
                        const double epsilon = levels[std::size_t(level)];
                        return "fourier:seed=" + std::to_string(seed) + ",harmonics=" + std::to_string(harmonics) +
                               (components > 1 ? ",components=" + std::to_string(components) : "") +
                               "|epsilon=" + format_number(epsilon) +
                               (uniformity ? "|uniformity=" + format_number(*uniformity) : "");
                      });
}

// Three point sets to one curve sampling: the degenerate families find most defects, and a
// sampling costs a medial axis to measure.
rc::Gen<Hunt_case> hunt_cases(const std::optional<certify::Theorem>& theorem, bool several_curves) {
  const auto as_points = rc::gen::map(point_sets(), [](std::vector<Point> points) { return Hunt_case{std::move(points), {}}; });
  const auto as_curve =
      rc::gen::map(curve_samplings(theorem ? std::optional(theorem->bound) : std::nullopt,
                                   theorem ? theorem->uniformity_below : std::nullopt, several_curves),
                   [](std::string curve) { return Hunt_case{{}, std::move(curve)}; });
  return rc::gen::oneOf(as_points, as_points, as_points, as_curve);
}

// ---- One run of the algorithm, in a worker process ------------------------------------

// What a run gave: edges (between input points unless `moved` is set), a clear error, or
// a defect.
struct Outcome {
  enum class Kind { edges, error, invalid, crash, hang } kind = Kind::edges;
  std::string message;
  std::vector<Edge> edges;
  std::vector<Point> moved;
};

std::string run_in_worker(const algorithms::Algorithm& algorithm, std::span<const Point> points) {
  std::ostringstream out;
  out.precision(17);
  try {
    const algorithms::Reconstruction result = algorithms::reconstruct(algorithm, points);
    const std::size_t count = result.points.empty() ? points.size() : result.points.size();
    for (std::size_t e = 0; e < result.edges.size(); ++e) {
      const auto [i, j] = result.edges[e];
      if (!(i < j && j < count) || (e > 0 && !(result.edges[e - 1] < result.edges[e])))
        return "invalid\nedge " + std::to_string(i) + " " + std::to_string(j) + " of " + std::to_string(count) +
               " points: out of range, a self-loop, unsorted or repeated";
    }
    out << "edges\n" << result.points.size() << '\n';
    for (const Point& p : result.points) out << p.x() << ' ' << p.y() << '\n';
    for (const auto& [i, j] : result.edges) out << i << ' ' << j << '\n';
  } catch (const Invalid_output& error) {
    return std::string("invalid\n") + error.what();
  } catch (const Program_crashed& error) {
    return std::string("crash\n") + error.what();
  } catch (const Program_timed_out& error) {
    return std::string("hang\n") + error.what();
  } catch (const std::exception& error) {
    return std::string("error\n") + error.what();
  }
  return out.str();
}

Outcome parse_outcome(const std::string& text) {
  std::istringstream in(text);
  std::string kind;
  std::getline(in, kind);
  Outcome outcome;
  if (kind != "edges") {
    outcome.kind = kind == "invalid" ? Outcome::Kind::invalid
                   : kind == "crash" ? Outcome::Kind::crash
                   : kind == "hang"  ? Outcome::Kind::hang
                                     : Outcome::Kind::error;
    std::getline(in, outcome.message);
    return outcome;
  }
  std::size_t moved = 0;
  in >> moved;
  for (std::size_t k = 0; k < moved; ++k) {
    double x = 0, y = 0;
    in >> x >> y;
    outcome.moved.emplace_back(x, y);
  }
  for (std::size_t i, j; in >> i >> j;) outcome.edges.emplace_back(i, j);
  return outcome;
}

// Runs the algorithm on each input in a worker process of its own, one after another.
std::vector<Outcome> run_each(const algorithms::Algorithm& algorithm, const std::vector<std::vector<Point>>& inputs,
                              double timeout) {
  std::vector<Outcome> outcomes(inputs.size());
  run_in_processes(
      inputs.size(), {.workers = 1, .timeout_seconds = timeout, .memory_limit_bytes = 8ull << 30},
      [&](std::size_t i) { return run_in_worker(algorithm, inputs[i]); },
      [&](std::size_t i, const Task_outcome& task) {
        if (task.kind == Task_outcome::Kind::finished) {
          outcomes[i] = parse_outcome(task.output);
        } else {
          outcomes[i].kind = task.kind == Task_outcome::Kind::timed_out ? Outcome::Kind::hang : Outcome::Kind::crash;
          outcomes[i].message = task.reason;
        }
      });
  return outcomes;
}

// ---- Checks -------------------------------------------------------------------------------

// No two points equal, no three collinear, no four cocircular, no two distances equal
// (exact predicates): where the output is the geometry's alone. On degenerate input an
// algorithm breaks ties, by index or by orientation, and the laws need not hold.
// Inputs above 16 points are not checked (the test is O(n^4), and exact at 2^±1000): a law's
// finding shrinks below that anyway.
bool general_position(const std::vector<Point>& p) {
  const std::size_t n = p.size();
  if (n > 16) return false;
  const auto compare_distance = geometry::Kernel().compare_distance_2_object();
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if (p[i] == p[j]) return false;
      pairs.emplace_back(i, j);
      for (std::size_t k = j + 1; k < n; ++k) {
        if (CGAL::collinear(p[i], p[j], p[k])) return false;
        for (std::size_t l = k + 1; l < n; ++l)
          if (CGAL::side_of_bounded_circle(p[i], p[j], p[k], p[l]) == CGAL::ON_BOUNDARY) return false;
      }
    }
  for (std::size_t a = 0; a < pairs.size(); ++a)
    for (std::size_t b = a + 1; b < pairs.size(); ++b)
      if (compare_distance(p[pairs[a].first], p[pairs[a].second], p[pairs[b].first], p[pairs[b].second]) == CGAL::EQUAL)
        return false;
  return true;
}

struct Defect {
  std::string kind, message;
  std::vector<Point> variant;  // the transformed input a law compared against, if any
};

// A case made: its points, and for a curve sampling the ground truth and measured sampling.
struct Made_case {
  std::vector<Point> points;
  std::optional<std::vector<Edge>> truth;
  std::optional<double> epsilon, uniformity;
};

Made_case made(const Hunt_case& c) {
  if (c.curve.empty()) return {c.points, {}, {}, {}};
  Bench_input input = std::move(make_bench_inputs(std::vector<std::string>{c.curve}).front());
  return {std::move(input.points), std::move(input.truth), input.epsilon, input.uniformity};
}

// Each point's first exact duplicate (PointSet's policy), so that edge sets compare
// whichever copy got the edges.
std::vector<std::size_t> representatives(const std::vector<Point>& points) {
  const geometry::PointSet set(points);
  std::vector<std::size_t> result;
  for (std::size_t i = 0; i < points.size(); ++i) result.push_back(set.input_index(set.kept_index(i)));
  return result;
}

// The edges as pairs of original points' representatives; variant index k is original
// point original_of[k].
std::vector<Edge> in_original_terms(const std::vector<Edge>& edges, const std::vector<std::size_t>& original_of,
                                    const std::vector<std::size_t>& representative) {
  std::vector<Edge> result;
  for (const auto& [i, j] : edges) {
    const std::size_t a = representative[original_of[i]], b = representative[original_of[j]];
    if (a != b) result.emplace_back(a, b);
  }
  return geometry::canonical_edges(std::move(result));
}

// The first dozen edges as "i-j ...": enough to see a small case, short for a sampled one.
std::string describe(const std::vector<Edge>& edges) {
  constexpr std::size_t shown = 12;
  std::string text;
  for (std::size_t k = 0; k < std::min(edges.size(), shown); ++k) {
    if (!text.empty()) text.push_back(' ');
    text.append(std::to_string(edges[k].first)).append("-").append(std::to_string(edges[k].second));
  }
  if (edges.size() > shown) text.append(" and ").append(std::to_string(edges.size() - shown)).append(" more");
  return text.empty() ? "(none)" : text;
}

std::optional<Defect> find_defect(const algorithms::Algorithm& algorithm, const Made_case& made_case, double timeout,
                                  const std::optional<certify::Theorem>& theorem) {
  const std::vector<Point>& points = made_case.points;
  const std::size_t n = points.size();
  std::vector<std::vector<Point>> inputs{points, points};
  std::vector<std::size_t> rotated(n), identity(n);  // the variant's point k is the input's rotated[k]
  for (std::size_t i = 0; i < n; ++i) identity[i] = i, rotated[i] = (i + 1) % n;
  std::vector<Point> permuted, doubled, mirrored;
  bool doubles_exactly = true;
  for (std::size_t i = 0; i < n; ++i) {
    permuted.push_back(points[rotated[i]]);
    doubled.emplace_back(2 * points[i].x(), 2 * points[i].y());
    mirrored.emplace_back(-points[i].x(), points[i].y());
    doubles_exactly = doubles_exactly && std::isfinite(doubled.back().x()) && std::isfinite(doubled.back().y());
  }
  // A curve sampling is in general position but for a rare draw, and too large to check:
  // the laws are left to the small point sets, whose findings are easier to read anyway.
  const bool sampled = made_case.truth.has_value();
  if (!sampled) inputs.insert(inputs.end(), {permuted, mirrored});
  if (!sampled && doubles_exactly) inputs.push_back(doubled);
  // The input alone first: most findings show there, and a clear error ends the case.
  std::vector<Outcome> outcomes = run_each(algorithm, {points}, timeout);
  if (outcomes[0].kind == Outcome::Kind::edges) {
    const std::vector<Outcome> rest = run_each(algorithm, {inputs.begin() + 1, inputs.end()}, timeout);
    outcomes.insert(outcomes.end(), rest.begin(), rest.end());
  }

  constexpr const char* names[] = {"input", "input, second run", "input rotated", "input mirrored", "input doubled"};
  for (std::size_t k = 0; k < outcomes.size(); ++k) {
    const Outcome& o = outcomes[k];
    const std::string where = std::string(" (") + names[k] + ")";
    const std::vector<Point> variant = k < 2 ? std::vector<Point>{} : inputs[k];
    if (o.kind == Outcome::Kind::crash) return Defect{"crash", o.message + where, variant};
    if (o.kind == Outcome::Kind::hang) return Defect{"hang", o.message + where, variant};
    if (o.kind == Outcome::Kind::invalid) return Defect{"invalid-output", o.message + where, variant};
  }
  const Outcome& first = outcomes[0];
  if (outcomes.size() < 2 || first.kind != Outcome::Kind::edges || outcomes[1].kind != Outcome::Kind::edges)
    return std::nullopt;
  if (first.edges != outcomes[1].edges || first.moved.size() != outcomes[1].moved.size() ||
      !std::equal(first.moved.begin(), first.moved.end(), outcomes[1].moved.begin()))
    return Defect{"not-deterministic", "two runs on the same input differ: " + describe(first.edges) + " / " +
                                           describe(outcomes[1].edges), {}};
  // The algorithm's own claim: exact under its epsilon (and uniformity) bound, as certify
  // classifies a case.
  if (sampled && theorem) {
    const bool exact = first.moved.empty() && first.edges == *made_case.truth;
    const double epsilon = made_case.epsilon.value_or(INFINITY);
    if (certify::classify(*theorem, epsilon, exact, made_case.uniformity.value_or(INFINITY)) == certify::Verdict::failure) {
      std::vector<Edge> wrong, missing;
      std::ranges::set_difference(first.edges, *made_case.truth, std::back_inserter(wrong));
      std::ranges::set_difference(*made_case.truth, first.edges, std::back_inserter(missing));
      std::string message = "measured epsilon " + format_number(epsilon) + " < " + format_number(theorem->bound) +
                            ", yet not exact:";
      if (!wrong.empty()) message += " " + std::to_string(wrong.size()) + " wrong edges (" + describe(wrong) + ")";
      if (!missing.empty()) message += " " + std::to_string(missing.size()) + " missing (" + describe(missing) + ")";
      return Defect{"not-exact-under-condition", message, {}};
    }
  }
  if (!first.moved.empty() || !general_position(points)) return std::nullopt;
  const std::vector<std::size_t> representative = representatives(points);
  const std::vector<Edge> expected = in_original_terms(first.edges, identity, representative);
  const std::pair<const char*, const std::vector<std::size_t>*> laws[] = {
      {"not-permutation-invariant", &rotated}, {"not-reflection-invariant", &identity}, {"not-scale-invariant", &identity}};
  for (std::size_t k = 2; k < outcomes.size(); ++k) {
    const Outcome& o = outcomes[k];
    if (o.kind != Outcome::Kind::edges || !o.moved.empty()) continue;  // a clear error on a variant is not a law broken
    const std::vector<Edge> seen = in_original_terms(o.edges, *laws[k - 2].second, representative);
    if (seen != expected)
      return Defect{laws[k - 2].first,
                    std::string("edges on the input: ") + describe(expected) + "; on the " + (names[k] + 6) +
                        " input, in the input's indices: " + describe(seen),
                    inputs[k]};
  }
  return std::nullopt;
}

// ---- Findings -------------------------------------------------------------------------------

void write_finding(Hunt_finding& finding, const Defect& defect, const Made_case& made_case,
                   const algorithms::Algorithm& algorithm, const Hunt_options& options, std::size_t number) {
  finding.directory = options.output / (finding.kind + "-" + std::to_string(number));
  std::filesystem::create_directories(finding.directory);
  geometry::write_points(finding.directory / "points.xy", finding.points);
  if (made_case.truth) geometry::write_edges(finding.directory / "truth.edges", *made_case.truth);
  if (!defect.variant.empty()) geometry::write_points(finding.directory / "variant.xy", defect.variant);
  std::error_code ignored;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ignored);
  std::ofstream replay(finding.directory / "replay.sh");
  replay << "#!/bin/sh\n# " << finding.kind << ": " << finding.message << "\n# found by curvebench hunt "
         << replay_arguments(algorithm) << " --seed " << options.seed << ", shrunk in " << finding.shrink_steps
         << " steps to " << finding.points.size() << " points"
         << (finding.curve.empty() ? "" : "\n# the sampling " + finding.curve + " (points.xy; truth.edges its ground truth)")
         << "\ncd \"$(dirname \"$0\")\"\n"
         << shell_quoted(self.string()) << " reconstruct " << replay_arguments(algorithm)
         << " -i points.xy -o edges.txt && cat edges.txt\n";
  if (made_case.truth)
    replay << shell_quoted(self.string()) << " evaluate -i points.xy -e edges.txt -g truth.edges\n";
  if (!defect.variant.empty())
    replay << "echo 'on variant.xy (the same points transformed):'\n"
           << shell_quoted(self.string()) << " reconstruct " << replay_arguments(algorithm)
           << " -i variant.xy -o variant-edges.txt && cat variant-edges.txt\n";
  replay.close();
  std::filesystem::permissions(finding.directory / "replay.sh", std::filesystem::perms::owner_exec,
                               std::filesystem::perm_options::add);
}

}  // namespace

Hunt_summary hunt(const Hunt_options& options) {
  const algorithms::Algorithm* algorithm = find_any_algorithm(options.algorithm);
  if (!algorithm) throw std::invalid_argument("unknown algorithm '" + options.algorithm + "' (see `curvebench list`)");
  const std::optional<certify::Theorem> theorem = certify::theorem_of(*algorithm);
  const auto start = Clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  Hunt_summary summary;
  std::map<std::string, std::size_t> found;  // per kind
  const rc::Gen<Hunt_case> generator = hunt_cases(theorem, algorithm->capabilities.multiple != algorithms::Support::no);
  const auto defect_of = [&](const Hunt_case& c, Made_case& made_case) -> std::optional<Defect> {
    try {
      made_case = made(c);
    } catch (const std::exception&) {
      return std::nullopt;  // a curve the sampler cannot sample: no case, and no defect of the algorithm
    }
    return find_defect(*algorithm, made_case, options.case_timeout, theorem);
  };
  for (std::uint64_t i = 0; elapsed() < options.seconds; ++i) {
    if (options.stop_after > 0 && summary.findings.size() >= options.stop_after) break;
    const rc::Shrinkable<Hunt_case> drawn = generator(rc::Random(options.seed * 0x9E3779B97F4A7C15ULL + i), 5 + int(i * 7 % 60));
    ++summary.cases;
    Made_case made_case;
    std::optional<Defect> defect = defect_of(drawn.value(), made_case);
    if (!defect || found[defect->kind] >= options.max_findings) continue;
    // Greedy shrinking: the first shrink that shows the same defect, until none does.
    rc::Shrinkable<Hunt_case> current = drawn;
    std::size_t steps = 0;
    const bool law = defect->kind.ends_with("-invariant");
    for (bool progress = true; progress && elapsed() < 2 * options.seconds + 30;) {
      progress = false;
      rc::Seq<rc::Shrinkable<Hunt_case>> shrinks = current.shrinks();
      while (rc::Maybe<rc::Shrinkable<Hunt_case>> next = shrinks.next()) {
        const Hunt_case candidate = next->value();
        // A law is only checked in general position: a shrink that leaves it cannot show one.
        if (law && !general_position(candidate.points)) continue;
        Made_case made_candidate;
        std::optional<Defect> again = defect_of(candidate, made_candidate);
        if (again && again->kind == defect->kind) {
          current = *next, defect = std::move(again), made_case = std::move(made_candidate), ++steps, progress = true;
          break;
        }
      }
    }
    Hunt_finding finding{defect->kind, defect->message, made_case.points, steps, {}, current.value().curve, made_case.epsilon};
    const std::size_t number = ++found[defect->kind];
    if (!options.output.empty()) write_finding(finding, *defect, made_case, *algorithm, options, number);
    summary.findings.push_back(std::move(finding));
  }
  summary.seconds = elapsed();
  return summary;
}

std::string hunt_summary_json(const Hunt_summary& summary, const Hunt_options& options) {
  nlohmann::json findings = nlohmann::json::array();
  for (const Hunt_finding& f : summary.findings) {
    nlohmann::json points = nlohmann::json::array();
    for (const auto& p : f.points) points.push_back({p.x(), p.y()});
    findings.push_back({{"kind", f.kind},
                        {"message", f.message},
                        {"points", points},
                        {"shrink_steps", f.shrink_steps},
                        {"replay", f.directory.empty() ? nlohmann::json() : nlohmann::json((f.directory / "replay.sh").string())}});
  }
  return nlohmann::json{{"algorithm", options.algorithm}, {"seed", options.seed}, {"cases", summary.cases},
                        {"seconds", summary.seconds}, {"findings", findings}}
      .dump(2);
}

}  // namespace curvebench::bench
