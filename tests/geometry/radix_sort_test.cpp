// radix_sort_by_key against std::stable_sort with the comparison it promises: `<` on the
// keys, -0 before +0, equal keys in their input order. The keys mix values that share
// digits (so passes are skipped) with signs, zeros, subnormals, infinities and huge
// magnitudes, on both sides of the size below which it hands over to std::stable_sort.
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "geometry/radix_sort.h"

namespace curvebench::geometry {
namespace {

using Keyed = std::pair<double, int>;  // (key, position in the input)

bool promised_order(double a, double b) { return a < b || (a == b && std::signbit(a) && !std::signbit(b)); }

std::vector<Keyed> oracle(std::vector<Keyed> records) {
  std::stable_sort(records.begin(), records.end(),
                   [](const Keyed& a, const Keyed& b) { return promised_order(a.first, b.first); });
  return records;
}

std::vector<Keyed> radix_sorted(std::vector<Keyed> records) {
  radix_sort_by_key(std::span(records), [](const Keyed& r) { return r.first; });
  return records;
}

rc::Gen<double> any_key() {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const auto special = rc::gen::element(0.0, -0.0, inf, -inf, std::numeric_limits<double>::denorm_min(),
                                        std::numeric_limits<double>::max(), -std::numeric_limits<double>::min(), 1.0);
  // Nearly equal keys: one magnitude, the last bits varying, as the lengths of an evenly
  // sampled curve's edges.
  const auto nearly_one = rc::gen::map(rc::gen::inRange(0, 64), [](int ulps) {
    double x = 0.25;
    for (int i = 0; i < ulps; ++i) x = std::nextafter(x, 1.0);
    return x;
  });
  const auto scaled = rc::gen::map(rc::gen::pair(rc::gen::inRange(-1000, 1000), rc::gen::inRange(-1074, 1000)),
                                   [](std::pair<int, int> m) { return std::ldexp(m.first, m.second); });
  return rc::gen::oneOf(special, nearly_one, scaled);
}

std::vector<Keyed> numbered(const std::vector<double>& keys) {
  std::vector<Keyed> records;
  for (const double k : keys) records.emplace_back(k, int(records.size()));
  return records;
}

TEST(RadixSortByKey, EmptyAndSingle) {
  EXPECT_TRUE(radix_sorted({}).empty());
  EXPECT_EQ(radix_sorted({{-0.0, 0}}), std::vector<Keyed>({{-0.0, 0}}));
}

TEST(RadixSortByKey, ZerosOfBothSignsAndEqualKeysKeepTheirPlaces) {
  std::vector<double> keys;
  for (int i = 0; i < 2000; ++i) keys.push_back(i % 4 == 0 ? 0.0 : i % 4 == 1 ? -0.0 : i % 4 == 2 ? 3.5 : -3.5);
  const auto sorted = radix_sorted(numbered(keys));
  ASSERT_EQ(sorted, oracle(numbered(keys)));
  // -3.5, -0, +0 and 3.5, 500 of each.
  EXPECT_TRUE(sorted[500].first == 0 && std::signbit(sorted[500].first));
  EXPECT_TRUE(sorted[1000].first == 0 && !std::signbit(sorted[1000].first));
}

RC_GTEST_PROP(RadixSortByKey, IsTheStableSortByKey, ()) {
  const auto keys = *rc::gen::container<std::vector<double>>(*rc::gen::inRange<std::size_t>(0, 3000), any_key());
  RC_ASSERT(radix_sorted(numbered(keys)) == oracle(numbered(keys)));
}

RC_GTEST_PROP(RadixSortByKey, IsTheStableSortByKeyOnAFewDistinctKeys, ()) {
  // A digit that takes two or three values in the whole input must still be sorted on.
  const auto pool = *rc::gen::nonEmpty(rc::gen::container<std::vector<double>>(*rc::gen::inRange(1, 4), any_key()));
  const auto keys =
      *rc::gen::container<std::vector<double>>(*rc::gen::inRange<std::size_t>(0, 3000), rc::gen::elementOf(pool));
  RC_ASSERT(radix_sorted(numbered(keys)) == oracle(numbered(keys)));
}

RC_GTEST_PROP(OrderedBits, IsStrictlyMonotoneInTheKey, (double a, double b)) {
  RC_PRE(!std::isnan(a) && !std::isnan(b));
  RC_ASSERT((ordered_bits(a) < ordered_bits(b)) == promised_order(a, b));
}

}  // namespace
}  // namespace curvebench::geometry
