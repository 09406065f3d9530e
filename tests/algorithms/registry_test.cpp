// Laws every registered algorithm obeys, whatever it does: the registry is consistent,
// parameters are checked, and degenerate input (0-3 points, cocircular grids, collinear
// runs, duplicates, extreme scales) gives canonical edges between input points, the same
// on every run and in any input order, without a crash.
#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <algorithm>
#include <numeric>
#include <set>
#include <string>

#include "algorithms/registry.h"
#include "tests/support/point_generators.h"

namespace curvebench::algorithms {
namespace {

std::vector<std::string> algorithm_names() {
  std::vector<std::string> names;
  for (const Algorithm& algorithm : registry()) names.emplace_back(algorithm.name);
  return names;
}

TEST(Registry, NamesAreUniqueAndFindable) {
  std::set<std::string_view> seen;
  for (const Algorithm& algorithm : registry()) {
    EXPECT_TRUE(seen.insert(algorithm.name).second) << algorithm.name;
    EXPECT_EQ(find_algorithm(algorithm.name), &algorithm);
    EXPECT_FALSE(algorithm.title.empty());
    EXPECT_FALSE(algorithm.reference.empty());
    EXPECT_FALSE(algorithm.capabilities.time_complexity.empty()) << algorithm.name;
    EXPECT_TRUE(static_cast<bool>(algorithm.reconstruct)) << algorithm.name;
  }
  EXPECT_EQ(find_algorithm("no-such-algorithm"), nullptr);
}

TEST(Registry, ConditionsAgreeWithTheGuaranteeColumn) {
  for (const Algorithm& algorithm : registry()) {
    const Sampling_condition& condition = algorithm.condition;
    if (condition.epsilon_below || condition.rho_below) {
      EXPECT_TRUE(algorithm.capabilities.guarantee) << algorithm.name;
      EXPECT_GT(condition.epsilon_below.value_or(1), 0);
      EXPECT_LT(condition.epsilon_below.value_or(0), 1);
    }
  }
}

TEST(Registry, DefaultsLieInTheirRanges) {
  for (const Algorithm& algorithm : registry())
    for (const Parameter& parameter : algorithm.parameters) {
      EXPECT_LE(parameter.minimum, parameter.default_value) << algorithm.name << ' ' << parameter.name;
      EXPECT_LE(parameter.default_value, parameter.maximum) << algorithm.name << ' ' << parameter.name;
      EXPECT_FALSE(parameter.meaning.empty()) << algorithm.name << ' ' << parameter.name;
    }
}

TEST(ParameterValues, ParseAndPrintRoundTrip) {
  const Parameter_values values = Parameter_values::parse("beta=1.25,alpha=0.5");
  EXPECT_EQ(values.to_string(), "alpha=0.5,beta=1.25");
  EXPECT_EQ(Parameter_values::parse(values.to_string()).values(), values.values());
  EXPECT_TRUE(Parameter_values::parse("").values().empty());
  for (const char* bad : {"beta", "=1", "beta=", "beta=1x", "beta=nan", "beta=inf", "a=1,,b=2"})
    EXPECT_THROW(Parameter_values::parse(bad), std::invalid_argument) << bad;
}

TEST(ParameterValues, AreCheckedAgainstTheAlgorithm) {
  const Algorithm& beta = *find_algorithm("beta-skeleton");
  const std::vector<Point> points{{0, 0}, {1, 0}, {0, 1}};
  EXPECT_THROW(reconstruct(beta, points, {{"gamma", 1}}), std::invalid_argument);
  EXPECT_THROW(reconstruct(beta, points, {{"beta", 0.5}}), std::invalid_argument);
  EXPECT_NO_THROW(reconstruct(beta, points, {{"beta", 2}}));
}

class Every_algorithm : public ::testing::TestWithParam<std::string> {
 protected:
  const Algorithm& algorithm() const { return *find_algorithm(GetParam()); }
};

// Valid, canonical edges between input points; none at a merged duplicate.
void expect_canonical(const Reconstruction& result, const std::vector<Point>& points) {
  const std::size_t n = result.points.empty() ? points.size() : result.points.size();
  for (std::size_t k = 0; k < result.edges.size(); ++k) {
    const auto [i, j] = result.edges[k];
    RC_ASSERT(i < j);
    RC_ASSERT(j < n);
    if (k > 0) RC_ASSERT(result.edges[k - 1] < result.edges[k]);
    if (result.points.empty())
      for (const std::size_t end : {i, j})
        RC_ASSERT(std::find(points.begin(), points.end(), points[end]) == points.begin() + end);
  }
}

TEST_P(Every_algorithm, HandlesTinyInputs) {
  const std::vector<std::vector<Point>> inputs{
      {}, {{1, 2}}, {{1, 2}, {1, 2}}, {{0, 0}, {1, 0}}, {{0, 0}, {1, 0}, {2, 0}}, {{0, 0}, {1, 0}, {0, 1}},
      {{0, 0}, {1, 0}, {0, 1}, {0, 0}}, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  for (const auto& points : inputs) {
    const Reconstruction result = reconstruct(algorithm(), points);
    for (const auto& [i, j] : result.edges) {
      EXPECT_LT(i, j);
      EXPECT_LT(j, points.size());
    }
    if (points.size() < 2) {
      EXPECT_TRUE(result.edges.empty()) << algorithm().name;
    }
  }
}

RC_GTEST_PROP(Every_algorithm_, DegenerateInputGivesCanonicalDeterministicEdges, ()) {
  const std::vector<Point> distinct_points = *testing::point_sets(40);
  // Duplicates: repeat a few points at the end.
  std::vector<Point> points = distinct_points;
  const auto repeats = *rc::gen::container<std::vector<std::size_t>>(rc::gen::inRange<std::size_t>(0, 1000));
  for (const std::size_t r : repeats)
    if (!distinct_points.empty() && points.size() < 60) points.push_back(distinct_points[r % distinct_points.size()]);
  for (const Algorithm& algorithm : registry()) {
    const Reconstruction first = reconstruct(algorithm, points);
    expect_canonical(first, points);
    const Reconstruction second = reconstruct(algorithm, points);
    RC_ASSERT(first.edges == second.edges);
    RC_ASSERT(first.points == second.points);
  }
}

// The curve as a set of segments between coordinates: what must not depend on the order
// the points came in (indices do, through the permutation and the merged duplicates).
std::set<std::pair<Point, Point>> segments(const Reconstruction& result, const std::vector<Point>& input) {
  const std::vector<Point>& points = result.points.empty() ? input : result.points;
  std::set<std::pair<Point, Point>> out;
  for (const auto& [i, j] : result.edges) out.insert(std::minmax(points[i], points[j]));
  return out;
}

// Ties between equal distances abound in these inputs (grids, circles, collinear runs);
// an algorithm that broke them by input index would follow the order here. Every
// algorithm with edges on its input points (edges_on_input sorts them first); those that
// move points are not yet held to it (Stretch-Denoise's output follows the input order
// on near-coincident points).
RC_GTEST_PROP(Every_algorithm_, AnyInputOrderGivesTheSameCurve, ()) {
  const std::vector<Point> points = *testing::point_sets(40);
  const auto keys = *rc::gen::container<std::vector<std::uint32_t>>(points.size(), rc::gen::arbitrary<std::uint32_t>());
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::ranges::stable_sort(order, [&](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });
  std::vector<Point> shuffled;
  for (const std::size_t i : order) shuffled.push_back(points[i]);
  for (const Algorithm& algorithm : registry()) {
    const Reconstruction result = reconstruct(algorithm, points), again = reconstruct(algorithm, shuffled);
    if (!result.points.empty()) continue;
    if (segments(result, points) != segments(again, shuffled) || result.points.size() != again.points.size())
      RC_FAIL(std::string(algorithm.name) + " gives another curve for the same points in another order");
  }
}

INSTANTIATE_TEST_SUITE_P(Registry, Every_algorithm, ::testing::ValuesIn(algorithm_names()),
                         [](const auto& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace curvebench::algorithms
