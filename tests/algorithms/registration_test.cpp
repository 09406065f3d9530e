// One's own algorithm in the registry (algorithms/registry.h), as a program built with
// curvebench_add_program registers it: a namespace-scope Registration, before main.
// The toy registered here joins the points in input order into a closed polygon, so its
// edges are known in closed form on any input.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <regex>
#include <stdexcept>
#include <string>

#include "algorithms/registry.h"

namespace curvebench::algorithms {
namespace {

std::vector<Edge> polygon_in_input_order(std::span<const Point> points) {
  std::vector<Edge> edges;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) edges.emplace_back(i, i + 1);
  if (points.size() > 2) edges.emplace_back(0, points.size() - 1);
  return edges;
}

const Registration toy{{
    .name = "toy-polygon",
    .title = "the points in input order, closed",
    .reference = "registration_test.cpp",
    .category = "test",
    .parameters = {},
    .capabilities = {},
    .condition = {},
    // Not edges_on_input, which would hand it the points sorted: the toy reads their order.
    .reconstruct = [](std::span<const Point> points, const Parameter_values&) {
      return Reconstruction{polygon_in_input_order(points), {}};
    },
}};

TEST(Registration, StandsAfterTheBuiltInsAndIsFoundByName) {
  const auto all = registry();
  const auto mine = registered_algorithms();
  ASSERT_EQ(mine.size(), 1u);
  EXPECT_EQ(mine.front().name, "toy-polygon");
  EXPECT_EQ(&all.back(), &mine.front());
  EXPECT_EQ(all.front().name, "alpha-shape");  // the built-ins keep the survey's order
  EXPECT_EQ(find_algorithm("toy-polygon"), &mine.front());
  const Algorithm* filtered = find_algorithm("toy-polygon+outlier-filter");
  ASSERT_NE(filtered, nullptr);
  EXPECT_EQ(filtered->title, "the points in input order, closed + outlier filter");
}

TEST(Registration, RunsBehindTheRegistrysDuplicateMerge) {
  // A square with its first corner repeated at the end: the duplicate is merged into index
  // 0, so the toy sees four points and its 4-cycle comes back on the input's indices.
  const std::vector<Point> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
  const Reconstruction result = reconstruct(*find_algorithm("toy-polygon"), square);
  EXPECT_EQ(result.edges, (std::vector<Edge>{{0, 1}, {0, 3}, {1, 2}, {2, 3}}));
}

Algorithm named(std::string_view name) {
  Algorithm algorithm = *find_algorithm("toy-polygon");
  algorithm.name = name;
  return algorithm;
}

TEST(Registration, RefusesABadDescriptionAndAnyRegistrationOnceRead) {
  (void)registry();
  EXPECT_THROW(register_algorithm(named("toy-polygon")), std::invalid_argument);  // taken
  EXPECT_THROW(register_algorithm(named("nn-crust")), std::invalid_argument);     // a built-in's
  EXPECT_THROW(register_algorithm(named("")), std::invalid_argument);
  EXPECT_THROW(register_algorithm(named("x+outlier-filter")), std::invalid_argument);
  EXPECT_THROW(register_algorithm(named("exec:my")), std::invalid_argument);
  Algorithm no_function = named("no-function");
  no_function.reconstruct = nullptr;
  EXPECT_THROW(register_algorithm(no_function), std::invalid_argument);
  Algorithm bad_default = named("bad-default");
  bad_default.parameters = {{.name = "k", .type = Parameter_type::real, .default_value = 5, .minimum = 0, .maximum = 1,
                             .meaning = "out of range"}};
  EXPECT_THROW(register_algorithm(bad_default), std::invalid_argument);
  // Valid, but too late: a pointer from find_algorithm() may be held.
  EXPECT_THROW(register_algorithm(named("fine-name")), std::logic_error);
  EXPECT_EQ(registered_algorithms().size(), 1u);
}

// The name rule, restated as a regular expression: every string is refused, as invalid
// unless it is a free name that the rule allows, and as too late if it is.
// Names over an alphabet of allowed and refused characters, so that both outcomes occur.
RC_GTEST_PROP(Registration, NamesAreCheckedByTheStatedRule, ()) {
  const std::string name = *rc::gen::container<std::string>(rc::gen::elementOf(std::string("nncrust-_.+:A 0")));
  (void)registry();
  static const std::regex allowed("[a-z0-9._-]+");
  const bool valid = std::regex_match(name, allowed) && !name.ends_with("+outlier-filter") &&
                     find_algorithm(name) == nullptr;
  RC_CLASSIFY(valid);
  const std::string kept(name);  // the registry would keep a view of it; it never does here
  try {
    register_algorithm(named(kept));
    RC_FAIL("registered after the registry was read");
  } catch (const std::logic_error& error) {
    const bool invalid = dynamic_cast<const std::invalid_argument*>(&error) != nullptr;
    RC_ASSERT(invalid == !valid);
  }
}

}  // namespace
}  // namespace curvebench::algorithms
