// Session algorithms (algorithms/registry.h's add_session_algorithm): added while the
// program runs, after the registry has been read, as the Python module adds a Python
// function. The toy added here joins the points in input order into an open chain, so its
// edges are known in closed form on any input.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <regex>
#include <stdexcept>
#include <string>

#include "algorithms/registry.h"

namespace curvebench::algorithms {
namespace {

std::vector<Edge> chain_in_input_order(std::span<const Point> points) {
  std::vector<Edge> edges;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) edges.emplace_back(i, i + 1);
  return edges;
}

// A description whose texts live only as long as this object: the registry must copy them.
struct Chain {
  std::string name, title = "chain of " + name, meaning = "unused, but listed",
                    parameter = "k_" + std::to_string(name.size());
  Algorithm algorithm() const {
    return {.name = name,
            .title = title,
            .reference = "session_algorithm_test.cpp",
            .category = "test",
            .parameters = {{.name = parameter, .type = Parameter_type::integer, .default_value = 2, .minimum = 1,
                            .maximum = 9, .meaning = meaning}},
            .capabilities = {.open = Support::yes, .time_complexity = "O(n)"},
            .condition = {.statement = "none"},
            .reconstruct = edges_on_input(chain_in_input_order)};
  }
};

const Algorithm& add_chain(const std::string& name) {
  Chain chain{name};
  const Algorithm& added = add_session_algorithm(chain.algorithm());
  chain.title = chain.meaning = chain.parameter = chain.name = std::string(40, '#');  // overwritten, then gone
  return added;
}

TEST(SessionAlgorithm, IsFoundByNameButNotListedAndKeepsItsOwnTexts) {
  const std::size_t listed = registry().size();  // read: registration is closed, sessions are not
  const Algorithm* added = &add_chain("session-chain");
  EXPECT_EQ(added->name, "session-chain");
  EXPECT_EQ(added->title, "chain of session-chain");
  ASSERT_EQ(added->parameters.size(), 1u);
  EXPECT_EQ(added->parameters[0].name, "k_13");
  EXPECT_EQ(added->parameters[0].meaning, "unused, but listed");
  EXPECT_EQ(added->capabilities.time_complexity, "O(n)");
  EXPECT_EQ(find_algorithm("session-chain"), added);
  EXPECT_EQ(registry().size(), listed);
  ASSERT_FALSE(session_algorithms().empty());
  EXPECT_EQ(session_algorithms().back(), added);
  const Algorithm* filtered = find_algorithm("session-chain+outlier-filter");
  ASSERT_NE(filtered, nullptr);
  EXPECT_EQ(filtered->title, "chain of session-chain + outlier filter");
  EXPECT_EQ(find_algorithm("session-chain+outlier-filter"), filtered);  // made once
}

TEST(SessionAlgorithm, RunsBehindTheRegistrysDuplicateMergeAndParameterCheck) {
  const Algorithm& chain = add_chain("session-chain-2");
  // Points 1 and 3 repeat point 0: merged into it, the chain sees 0, 2, 4 and joins them in
  // that order, on the input's indices.
  const std::vector<Point> points{{0, 0}, {0, 0}, {1, 0}, {0, 0}, {2, 5}};
  EXPECT_EQ(reconstruct(chain, points).edges, (std::vector<Edge>{{0, 2}, {2, 4}}));
  EXPECT_THROW(reconstruct(chain, points, {{"k_15", 0.5}}), std::invalid_argument);  // not whole, and out of range
  EXPECT_THROW(reconstruct(chain, points, {{"nope", 1}}), std::invalid_argument);
  EXPECT_NO_THROW(reconstruct(chain, points, {{"k_15", 3}}));
}

TEST(SessionAlgorithm, RefusesWhatRegisterAlgorithmRefusesAndTakenNames) {
  (void)add_chain("session-chain-3");
  for (const std::string name : {"session-chain-3", "nn-crust", "", "Upper", "x+outlier-filter"}) {  // taken or invalid
    const Chain chain{name};
    EXPECT_THROW(add_session_algorithm(chain.algorithm()), std::invalid_argument) << name;
  }
  const Chain no_function{"no-function"}, bad_default{"bad-default"};
  Algorithm without = no_function.algorithm(), outside = bad_default.algorithm();
  without.reconstruct = nullptr;
  outside.parameters[0].default_value = 10;
  EXPECT_THROW(add_session_algorithm(without), std::invalid_argument);
  EXPECT_THROW(add_session_algorithm(outside), std::invalid_argument);
  EXPECT_EQ(find_algorithm("no-function"), nullptr);
  EXPECT_EQ(find_algorithm("bad-default"), nullptr);
}

// The name rule, restated as a regular expression; each name tried at most once.
RC_GTEST_PROP(SessionAlgorithm, NamesAreCheckedByTheStatedRule, ()) {
  const std::string name = *rc::gen::container<std::string>(rc::gen::elementOf(std::string("session-_.+:A 0")));
  static const std::regex allowed("[a-z0-9._-]+");
  const bool free = find_algorithm(name) == nullptr;
  const bool valid = std::regex_match(name, allowed) && !name.ends_with("+outlier-filter") && free;
  RC_CLASSIFY(valid);
  try {
    const Algorithm& added = add_chain(name);
    RC_ASSERT(valid);
    RC_ASSERT(find_algorithm(name) == &added);
  } catch (const std::invalid_argument&) {
    RC_ASSERT(!valid);
  }
}

}  // namespace
}  // namespace curvebench::algorithms
