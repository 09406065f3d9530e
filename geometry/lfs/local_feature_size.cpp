#include "geometry/lfs/local_feature_size.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry/bounding_box_diagonal.h"
#include "geometry/curves/curve_crossings.h"
#include "geometry/lfs/nearest_point_index.h"

namespace curvebench::geometry {
namespace {

constexpr int initial_points_per_piece = 16;
constexpr int maximum_splits_per_round = 16;  // an early estimate may be far off: refine it step by step
constexpr int maximum_rounds = 200;
constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr std::uint64_t unknown = 0xfff8'dead'beef'0001;  // a NaN that lfs never is

double piece_count(const Curve_component& component) { return static_cast<double>(component.piece_count()); }

std::vector<Point> points_at(const Curve& curve, const std::vector<std::vector<double>>& parameters) {
  std::vector<Point> points;
  for (std::size_t c = 0; c < curve.components.size(); ++c)
    for (const double s : parameters[c]) points.push_back(curve.components[c].point(s));
  return points;
}

std::vector<Sample_chain> chains_of(const Curve& curve, const std::vector<std::vector<double>>& parameters) {
  std::vector<Sample_chain> chains;
  for (std::size_t c = 0; c < curve.components.size(); ++c) chains.push_back({parameters[c].size(), curve.components[c].closed()});
  return chains;
}

std::vector<Point> points_of(std::span<const Sharp_point> sharp_points) {
  std::vector<Point> points;
  for (const Sharp_point& sharp : sharp_points) points.push_back(sharp.point);
  return points;
}

// The medial axis of the dense sample at `parameters`, with the exact points given.
Medial_axis medial_axis_at(const Curve& curve, const std::vector<std::vector<double>>& parameters,
                           std::span<const Sharp_point> sharp_points, std::span<const Point> branch_ends = {}) {
  std::vector<Point> exact = points_of(sharp_points);
  exact.insert(exact.end(), branch_ends.begin(), branch_ends.end());
  return Medial_axis(points_at(curve, parameters), chains_of(curve, parameters), exact);
}

// Cuts every chord of the dense sample that is long for the lfs estimate at its ends and
// the radius of curvature at its middle. Returns whether any was cut.
bool refine(const Curve_component& component, std::vector<double>& parameters, const Medial_axis& axis, double density,
            double minimum_spacing) {
  std::vector<double> refined;
  const std::size_t chords = component.closed() ? parameters.size() : parameters.size() - 1;
  // A chord's end is the next chord's start: its point and lfs are computed once.
  struct End {
    Point point;
    double lfs = 0;
    bool lfs_known = false;
  };
  const auto lfs_of = [&axis](End& end) {
    if (!end.lfs_known) end.lfs = axis.distance(end.point), end.lfs_known = true;
    return end.lfs;
  };
  End start;
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    refined.push_back(parameters[i]);
    if (i >= chords) continue;
    const double s0 = parameters[i], s1 = i + 1 < parameters.size() ? parameters[i + 1] : parameters[0] + piece_count(component);
    if (i == 0) start = {component.point(s0)};
    End end{component.point(s1)};
    const double chord = std::sqrt(CGAL::squared_distance(start.point, end.point));
    if (chord <= minimum_spacing) {
      start = end;
      continue;
    }
    const double curvature = std::abs(component.curvature((s0 + s1) / 2));
    const double local = std::min({lfs_of(start), lfs_of(end), curvature > 0 ? 1 / curvature : infinity});
    start = end;
    const double pieces = std::min<double>(std::ceil(chord * density / local), maximum_splits_per_round);
    for (int k = 1; k < pieces; ++k) {
      const double s = s0 + (s1 - s0) * k / pieces;
      refined.push_back(s < piece_count(component) || !component.closed() ? s : s - piece_count(component));
    }
  }
  std::sort(refined.begin(), refined.end());  // a closed component's last chord puts points before its first
  const bool changed = refined.size() != parameters.size();
  parameters = std::move(refined);
  return changed;
}

bool same_parameter(const Curve_component& component, double s, double t) {
  const double n = piece_count(component), tolerance = 1e-12 * n;
  const double d = std::abs(s - t);
  return d <= tolerance || (component.closed() && std::abs(d - n) <= tolerance);
}

// Signed curvature of a piece at t (at t = 0 or 1: that end's one-sided value).
double curvature_of(const Curve_piece& piece, double t) {
  const Vector d = piece.derivative(t), dd = piece.second_derivative(t);
  const double speed = std::sqrt(d * d);
  return CGAL::determinant(d, dd) / (speed * speed * speed);
}

// Where sign x curvature peaks on [low, high] of a piece (golden-section search); a
// one-sided maximum at an end of the piece is that end itself.
double curvature_maximum(const Curve_piece& piece, double sign, double low, double high) {
  constexpr double golden = 0.6180339887498949;
  for (int step = 0; step < 60 && high - low > 1e-15; ++step) {
    const double a = high - golden * (high - low), b = low + golden * (high - low);
    if (sign * curvature_of(piece, a) < sign * curvature_of(piece, b))
      low = a;
    else
      high = b;
  }
  double u = (low + high) / 2;
  for (const double end : {0.0, 1.0})
    if (std::abs(u - end) <= 1e-9 && sign * curvature_of(piece, end) >= sign * curvature_of(piece, u)) u = end;
  return u;
}

// The ends of the medial axis' branches: the centres of curvature at the local maxima of
// |curvature| (inside a piece, or at a join from either side) whose osculating disc holds
// no point of the dense sample. Such a disc is the largest empty one touching the curve
// there, so its centre is a medial point. Voronoi vertices of the dense sample reach a
// branch's end only to about |dR/ds| times the sample spacing (R the radius of curvature,
// which changes fastest there): on f5.svg, where the curvature jumps 50-fold at a Bézier
// join, they stopped 20 units (16 % of lfs) short of it and lfs read that much high.
//
// A maximum whose radius is below `resolution` (a length) is a point where the medial axis reaches
// the curve: a Bézier end whose handle lies on it (Inkscape's "c 0,0", 257 of them in
// data/svg/, 251 at the ends of open strokes), where the curvature is unbounded
// (cubic_bezier.h). Those are sharp points, as corners are.
struct Branch_ends {
  std::vector<Point> centres;
  std::vector<Sharp_point> singular;
};

Branch_ends branch_ends(const Curve& curve, const std::vector<std::vector<double>>& parameters, double resolution) {
  const std::vector<Point> sample = points_at(curve, parameters);
  const Nearest_point_index nearest(sample);
  Branch_ends found;
  for (std::size_t c = 0; c < curve.components.size(); ++c) {
    const Curve_component& component = curve.components[c];
    const std::vector<double>& dense = parameters[c];
    for (std::size_t i = 0; i < component.piece_count(); ++i) {
      const Curve_piece& piece = component.piece(i);
      // The piece's own parameters: its ends and the dense ones inside.
      std::vector<double> t{0};
      for (auto it = std::upper_bound(dense.begin(), dense.end(), double(i)); it != dense.end() && *it < double(i + 1); ++it)
        t.push_back(*it - double(i));
      t.push_back(1);
      std::vector<double> kappa;
      for (const double u : t) kappa.push_back(curvature_of(piece, u));
      for (const double sign : {1.0, -1.0})
        for (std::size_t j = 0; j < t.size(); ++j) {
          const auto value = [&](std::size_t k) { return sign * kappa[k]; };
          if (!(value(j) > 0) || (j > 0 && value(j - 1) > value(j)) || (j + 1 < t.size() && value(j + 1) > value(j))) continue;
          const double u = curvature_maximum(piece, sign, t[j > 0 ? j - 1 : 0], t[j + 1 < t.size() ? j + 1 : j]);
          const double k = curvature_of(piece, u);
          if (!(sign * k > 0)) continue;
          if (!(1 / std::abs(k) > resolution)) {
            double at = double(i) + u;
            if (component.closed() && at >= piece_count(component)) at -= piece_count(component);
            const bool corner = std::ranges::any_of(component.corners(), [&](double s) { return same_parameter(component, s, at); });
            const bool listed = std::ranges::any_of(found.singular, [&](const Sharp_point& p) {
              return p.location.component == c && same_parameter(component, p.location.parameter, at);
            });
            if (!corner && !listed) found.singular.push_back({piece.point(u), {c, at}, Sharp_point::Kind::unbounded_curvature});
            continue;
          }
          const Vector d = piece.derivative(u);
          const Vector normal = d.perpendicular(CGAL::COUNTERCLOCKWISE) / std::sqrt(d * d);
          const Point centre = piece.point(u) + normal / k;
          if (nearest.distance(centre) >= (1 - 1e-9) / std::abs(k)) found.centres.push_back(centre);
        }
    }
  }
  return found;
}

}  // namespace

struct Local_feature_size::Estimate {
  double bounding_box_diagonal = 0;
  std::vector<std::vector<double>> dense_parameters;
  std::vector<Sharp_point> sharp_points;
  Medial_axis medial_axis;
};

Local_feature_size::Local_feature_size(const Curve& curve, double density, double resolution)
    : Local_feature_size(curve, [&] {
        if (!(density > 0 && density < infinity) || !(resolution > 0 && resolution < infinity))
          throw std::invalid_argument("local feature size: density and resolution must be positive and finite");
        std::vector<std::vector<double>> parameters;
        std::vector<Sharp_point> sharp_points;
        for (std::size_t c = 0; c < curve.components.size(); ++c) {
          const Curve_component& component = curve.components[c];
          auto& s = parameters.emplace_back();
          for (std::size_t k = 0; k < component.piece_count() * initial_points_per_piece; ++k)
            s.push_back(static_cast<double>(k) / initial_points_per_piece);
          if (!component.closed()) s.push_back(piece_count(component));
          for (const double corner : component.corners()) sharp_points.push_back({component.point(corner), {c, corner}});
        }
        const std::vector<Point> initial = points_at(curve, parameters);
        const double diagonal = geometry::bounding_box_diagonal(initial);

        // The branch ends found on the first sample serve the refinement; those of the
        // final sample (whose emptiness test is finer) replace them if they differ.
        Branch_ends ends = branch_ends(curve, parameters, resolution * diagonal);
        sharp_points.insert(sharp_points.end(), ends.singular.begin(), ends.singular.end());
        Medial_axis axis = medial_axis_at(curve, parameters, sharp_points, ends.centres);
        for (int round = 0; round < maximum_rounds; ++round) {
          bool changed = false;
          for (std::size_t c = 0; c < curve.components.size(); ++c)
            changed |= refine(curve.components[c], parameters[c], axis, density, resolution * diagonal);
          if (!changed) break;
          axis = medial_axis_at(curve, parameters, sharp_points, ends.centres);
        }
        const std::vector<Curve_crossing> crossings = curve_crossings(curve, parameters);
        for (const Curve_crossing& crossing : crossings) {
          sharp_points.push_back({crossing.point, crossing.first, Sharp_point::Kind::crossing});
          sharp_points.push_back({crossing.point, crossing.second, Sharp_point::Kind::crossing});
        }
        const std::vector<Point> final_centres = branch_ends(curve, parameters, resolution * diagonal).centres;
        if (!crossings.empty() || final_centres != ends.centres)
          axis = medial_axis_at(curve, parameters, sharp_points, final_centres);
        return Estimate{diagonal, std::move(parameters), std::move(sharp_points), std::move(axis)};
      }()) {}

Local_feature_size::Local_feature_size(const Curve& curve, Estimate estimate)
    : curve_(curve),
      bounding_box_diagonal_(estimate.bounding_box_diagonal),
      dense_parameters_(std::move(estimate.dense_parameters)),
      sharp_points_(std::move(estimate.sharp_points)),
      sharp_parameters_(curve.components.size()),
      medial_axis_(std::move(estimate.medial_axis)) {
  for (const Sharp_point& sharp : sharp_points_)
    sharp_parameters_[sharp.location.component].push_back(sharp.location.parameter);
  for (auto& parameters : sharp_parameters_) std::sort(parameters.begin(), parameters.end());
  for (std::size_t c = 0; c < curve_.components.size(); ++c) {
    const std::size_t gaps = curve_.components[c].closed() ? dense_parameters_[c].size()
                                                           : std::max<std::size_t>(dense_parameters_[c].size(), 1) - 1;
    auto& slots = cache_.emplace_back(std::make_unique<std::atomic<std::uint64_t>[]>(gaps * cached_subdivisions));
    for (std::size_t i = 0; i < gaps * cached_subdivisions; ++i) slots[i].store(unknown, std::memory_order_relaxed);
  }
}

double Local_feature_size::at(std::size_t component, double s) const {
  std::atomic<std::uint64_t>* const slot = cached_at(component, s);
  if (slot == nullptr) return uncached_at(component, s);
  const std::uint64_t known = slot->load(std::memory_order_relaxed);
  if (known != unknown) return std::bit_cast<double>(known);
  const double value = uncached_at(component, s);
  if (std::bit_cast<std::uint64_t>(value) != unknown) slot->store(std::bit_cast<std::uint64_t>(value), std::memory_order_relaxed);
  return value;
}

// The slot of s if it is exactly a grid point knot + (next knot - knot) * k / 8 of two
// consecutive dense parameters (as grid() computes it; for k = 2 j it is the same double
// as grid()'s (next - knot) * j / 4), or null.
std::atomic<std::uint64_t>* Local_feature_size::cached_at(std::size_t component, double s) const {
  // Queries mostly go along the curve: try this thread's last gap (of whichever
  // component: only compared, never trusted) and the next one before searching.
  thread_local const double* last_parameters = nullptr;
  thread_local std::size_t last_gap = 0;
  if (component >= dense_parameters_.size()) return nullptr;
  const std::vector<double>& dense = dense_parameters_[component];
  if (dense.empty() || !(s >= dense.front())) return nullptr;
  std::size_t i = last_gap;
  if (last_parameters != dense.data() || !(i + 1 < dense.size() && dense[i] <= s)) {
    i = static_cast<std::size_t>(std::upper_bound(dense.begin(), dense.end(), s) - dense.begin()) - 1;
  } else if (!(s < dense[i + 1])) {
    if (i + 2 < dense.size() && s < dense[i + 2])
      ++i;
    else
      i = static_cast<std::size_t>(std::upper_bound(dense.begin() + i + 1, dense.end(), s) - dense.begin()) - 1;
  }
  last_parameters = dense.data(), last_gap = i;
  const Curve_component& c = curve_.components[component];
  if (i + 1 == dense.size() && !c.closed()) return nullptr;
  const double knot = dense[i], next = i + 1 < dense.size() ? dense[i + 1] : dense.front() + piece_count(c);
  const double gap = next - knot;
  int k = 0;
  if (s != knot) {
    const double steps = (s - knot) / gap * cached_subdivisions;
    if (!(steps >= 0.5 && steps < cached_subdivisions - 0.5)) return nullptr;
    k = static_cast<int>(steps + 0.5);
  }
  if (std::bit_cast<std::uint64_t>(knot + gap * k / cached_subdivisions) != std::bit_cast<std::uint64_t>(s)) return nullptr;
  return &cache_[component][i * cached_subdivisions + static_cast<std::size_t>(k)];
}

double Local_feature_size::uncached_at(std::size_t component, double s) const {
  const Curve_component& c = curve_.components.at(component);
  // The sharp parameters t that same_parameter(c, s, t) could accept: within its
  // tolerance of s, or of s -+ n on a closed component, widened far beyond rounding.
  const std::vector<double>& sharp = sharp_parameters_[component];
  if (!sharp.empty()) {
    const double n = piece_count(c), window = 1e-12 * n + 1e-9 * (2 * n + std::abs(s));
    const auto near = [&](double center) {
      for (auto it = std::lower_bound(sharp.begin(), sharp.end(), center - window); it != sharp.end() && *it <= center + window;
           ++it)
        if (same_parameter(c, s, *it)) return true;
      return false;
    };
    if (near(s) || (c.closed() && (near(s - n) || near(s + n)))) return 0;
  }
  return at(c.point(s));
}

std::vector<double> Local_feature_size::grid(std::size_t component, double s0, double s1, int subdivisions) const {
  const Curve_component& c = curve_.components.at(component);
  const std::vector<double>& dense = dense_parameters_[component];
  std::vector<double> knots{s0};
  const double n = piece_count(c);
  for (double base = c.closed() ? std::floor(s0 / n) * n : 0; base < s1; base += n) {
    for (auto it = std::upper_bound(dense.begin(), dense.end(), s0 - base); it != dense.end() && *it + base < s1; ++it)
      knots.push_back(*it + base);
    if (!c.closed()) break;
  }
  knots.push_back(s1);
  std::vector<double> cells;
  cells.reserve((knots.size() - 1) * subdivisions + 1);
  for (std::size_t i = 0; i + 1 < knots.size(); ++i)
    for (int k = 0; k < subdivisions; ++k) cells.push_back(knots[i] + (knots[i + 1] - knots[i]) * k / subdivisions);
  cells.push_back(s1);
  return cells;
}

double relative_distance(double distance, double lfs, double minimum_lfs) {
  const double scale = std::max(lfs, minimum_lfs);
  if (scale == 0) return distance == 0 ? 0 : infinity;
  return distance / scale;
}

}  // namespace curvebench::geometry
