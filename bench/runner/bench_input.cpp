#include "bench/runner/bench_input.h"

#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>

#include "bench/runner/resources.h"
#include "certify/sampling_measure.h"
#include "geometry/curves/curve_spec.h"
#include "geometry/io/point_io.h"
#include "geometry/sampling/sampling.h"
#include "geometry/sampling/sampling_noise.h"

namespace curvebench::bench {
namespace {

using Settings = std::map<std::string, double, std::less<>>;

const std::string_view known_keys[] = {"epsilon", "walk",      "rho",      "uniform", "per-circle", "uniformity",
                                       "crossings", "noise",   "lfs-noise", "outliers", "seed"};
const std::string_view sampler_keys[] = {"epsilon", "walk", "rho", "uniform", "per-circle"};

Settings parse_settings(std::string_view name) {
  Settings settings;
  std::string_view rest = name.substr(input_source(name).size());
  while (!rest.empty()) {
    rest.remove_prefix(1);  // the '|'
    const std::string_view item = rest.substr(0, rest.find('|'));
    rest.remove_prefix(item.size());
    const auto equals = item.find('=');
    const std::string_view key = item.substr(0, equals);
    if (equals == std::string_view::npos || std::ranges::find(known_keys, key) == std::end(known_keys))
      throw std::invalid_argument("input " + std::string(name) + ": unknown setting '" + std::string(item) + "'");
    const std::string value(item.substr(equals + 1));
    std::size_t used = 0;
    double number = 0;
    try {
      number = std::stod(value, &used);
    } catch (const std::exception&) {
    }
    if (used == 0 || used != value.size() || !std::isfinite(number) || number < 0)
      throw std::invalid_argument("input " + std::string(name) + ": '" + value + "' is not a number >= 0");
    if (!settings.emplace(key, number).second)
      throw std::invalid_argument("input " + std::string(name) + ": " + std::string(key) + " given twice");
  }
  return settings;
}

std::size_t count_of(const Settings& settings, std::string_view key, std::string_view name) {
  const double value = settings.find(key)->second;
  if (value != std::floor(value) || value > 1e9)
    throw std::invalid_argument("input " + std::string(name) + ": " + std::string(key) + " must be a whole number");
  return static_cast<std::size_t>(value);
}

// The noise and outlier settings, in the order the header gives.
geometry::Sample perturbed(geometry::Sample sample, const Settings& settings, const geometry::Local_feature_size* lfs) {
  const auto seed = static_cast<std::uint64_t>(settings.contains("seed") ? settings.find("seed")->second : 0);
  if (const auto it = settings.find("noise"); it != settings.end())
    sample = geometry::with_uniform_noise(std::move(sample), it->second, seed + 1);
  if (const auto it = settings.find("lfs-noise"); it != settings.end())
    sample = geometry::with_lfs_noise(*lfs, std::move(sample), it->second, seed + 2);
  if (const auto it = settings.find("outliers"); it != settings.end())
    sample = geometry::with_outliers(std::move(sample), it->second, seed + 3);
  return sample;
}

geometry::Sample drawn(const geometry::Local_feature_size& lfs, const Settings& settings, std::string_view name) {
  const char* chosen = nullptr;
  for (const std::string_view key : sampler_keys)
    if (settings.contains(key)) {
      if (chosen) throw std::invalid_argument("input " + std::string(name) + ": more than one sampler");
      chosen = key.data();
    }
  if (!chosen) throw std::invalid_argument("input " + std::string(name) + ": no sampler (epsilon=, uniform=, ...)");
  const std::string_view key = chosen;
  const double value = settings.find(key)->second, floor = geometry::default_minimum_lfs(lfs);
  if (settings.contains("uniformity") && key != "epsilon")
    throw std::invalid_argument("input " + std::string(name) + ": uniformity= grades an epsilon= sampling only");
  if (key == "epsilon" && settings.contains("uniformity"))
    return geometry::graded_epsilon_sampling(lfs, value, settings.find("uniformity")->second, floor);
  if (key == "epsilon") return geometry::safe_epsilon_sampling(lfs, value, floor);
  if (key == "walk") return geometry::epsilon_sampling(lfs, value, floor);
  if (key == "rho") return geometry::safe_rho_sampling(lfs, value, floor);
  if (key == "uniform") return geometry::uniform_sampling(lfs, count_of(settings, key, name));
  const double per_circle = static_cast<double>(count_of(settings, key, name));
  if (per_circle < 1) throw std::invalid_argument("input " + std::string(name) + ": per-circle must be >= 1");
  return geometry::uniform_sampling(
      lfs, static_cast<std::size_t>(std::ceil(lfs.curve().length() * per_circle / (2 * std::numbers::pi))));
}

// The sampler's points, with a sample at every crossing if `crossings=1`.
geometry::Sample sampled(const geometry::Local_feature_size& lfs, const Settings& settings, std::string_view name) {
  geometry::Sample sample = drawn(lfs, settings, name);
  const auto crossings = settings.find("crossings");
  if (crossings == settings.end() || crossings->second == 0) return sample;
  if (crossings->second != 1) throw std::invalid_argument("input " + std::string(name) + ": crossings must be 0 or 1");
  return geometry::with_crossing_samples(lfs, std::move(sample));
}

// A curve spec with its file resolved: svg:FILE[,corner=DEGREES], truth:POINTS:EDGES.
std::string resolved_spec(std::string_view spec) {
  if (spec.starts_with("svg:")) {
    const auto [file, options] = geometry::split_svg_options(spec.substr(4));
    return "svg:" + resolve_data_path(file).string() + std::string(options);
  }
  if (spec.starts_with("truth:")) {
    const std::string_view files = spec.substr(6);
    const auto colon = files.find(':');
    if (colon != std::string_view::npos)
      return "truth:" + resolve_data_path(files.substr(0, colon)).string() + ":" +
             resolve_data_path(files.substr(colon + 1)).string();
  }
  return std::string(spec);
}

}  // namespace

Polyline dense_polyline(const geometry::Local_feature_size& lfs) {
  Polyline result;
  const double tolerance = 1e-4 * lfs.bounding_box_diagonal();
  for (const geometry::Curve_component& component : lfs.curve().components) {
    const std::size_t first = result.points.size();
    for (const Point& p : component.polyline(tolerance)) result.points.push_back(p);
    for (std::size_t i = first; i + 1 < result.points.size(); ++i) result.edges.emplace_back(i, i + 1);
    if (component.closed() && result.points.size() - first > 2) result.edges.emplace_back(result.points.size() - 1, first);
  }
  return result;
}

std::string_view input_source(std::string_view name) { return name.substr(0, name.find('|')); }

std::filesystem::path resolve_data_path(const std::filesystem::path& path) {
  if (path.is_absolute() || std::filesystem::exists(path)) return path;
  const std::filesystem::path shipped = resource_root() / path;
  return std::filesystem::exists(shipped) ? shipped : path;
}

std::vector<Bench_input> make_bench_inputs(std::span<const std::string> names) {
  std::vector<Bench_input> inputs;
  if (names.empty()) return inputs;
  const std::string_view source = input_source(names.front());
  for (const std::string& name : names)
    if (input_source(name) != source)
      throw std::invalid_argument("inputs of different sources: " + names.front() + ", " + name);

  if (source.starts_with("file:")) {
    const std::vector<Point> points = geometry::read_point_file(resolve_data_path(source.substr(5))).points;
    for (const std::string& name : names) {
      const Settings settings = parse_settings(name);
      for (const std::string_view key : {"epsilon", "walk", "rho", "uniform", "per-circle", "uniformity", "crossings", "lfs-noise"})
        if (settings.contains(key))
          throw std::invalid_argument("input " + name + ": a point file takes no " + std::string(key));
      geometry::Sample sample;
      sample.points = points;
      sample.labels.assign(points.size(), geometry::Sample_label::curve_point);
      sample.locations.resize(points.size());
      sample.lfs.assign(points.size(), std::numeric_limits<double>::quiet_NaN());
      inputs.push_back({name, perturbed(std::move(sample), settings, nullptr).points, std::nullopt, nullptr});
    }
    return inputs;
  }

  const geometry::Local_feature_size lfs(geometry::make_curve(resolved_spec(source)));
  const auto curve = std::make_shared<const Polyline>(dense_polyline(lfs));
  for (const std::string& name : names) {
    const Settings settings = parse_settings(name);
    geometry::Sample sample = perturbed(sampled(lfs, settings, name), settings, &lfs);
    Bench_input input{name, {}, geometry::canonical_edges(sample.edges), curve};
    if (!settings.contains("noise") && !settings.contains("lfs-noise") && !settings.contains("outliers")) {
      input.epsilon = certify::measure_epsilon(lfs, sample.points, 0).epsilon;
      input.rho = certify::measure_rho(lfs, sample, 0).rho;
      input.uniformity = certify::measure_uniformity(sample.points, sample.edges).uniformity;
    }
    input.points = std::move(sample.points);
    inputs.push_back(std::move(input));
  }
  return inputs;
}

}  // namespace curvebench::bench
