// Conformance with the authors' own programs on their own data: each algorithm whose
// reference program is public is run here on the point sets its authors published, and
// compared with what that program outputs on them. The reference outputs were recorded
// from the authors' programs built unchanged apart from a headless driver (each table
// below names its program); only their shape is kept here (edge count, components,
// closed components, open ends, isolated points, and an FNV-1a hash of the edge list),
// since the Crawl figures may not be redistributed. Tests on them read ../shared/data/crawl/
// and skip, saying so, where it is absent; those on bundled data (data/) always run.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "algorithms/registry.h"
#include "geometry/io/point_io.h"

namespace curvebench::algorithms {
namespace {

namespace fs = std::filesystem;

const fs::path kSharedData = CURVEBENCH_SHARED_DATA_DIR;

// What a reference program gave on one point set.
struct Reference {
  std::string_view figure;  // file name without .txt
  std::size_t edges, components, closed, open_ends, isolated;
  std::uint64_t edge_hash;  // of the canonical edge list, see edge_hash()
};

// FNV-1a over "i j\n" per edge, i < j, sorted: the edges on input indices, a duplicate
// point standing for its first occurrence (as reconstruct() names them).
std::uint64_t edge_hash(const std::vector<Edge>& edges) {
  std::uint64_t hash = 0xcbf29ce484222325u;
  for (const auto& [i, j] : edges)
    for (const char c : std::to_string(i) + " " + std::to_string(j) + "\n") {
      hash ^= static_cast<unsigned char>(c);
      hash *= 0x100000001b3u;
    }
  return hash;
}

struct Shape {
  std::size_t edges, components, closed, open_ends, isolated;
  bool operator==(const Shape&) const = default;
};

std::ostream& operator<<(std::ostream& out, const Shape& s) {
  return out << s.edges << " edges, " << s.components << " components (" << s.closed << " closed), " << s.open_ends
             << " open ends, " << s.isolated << " isolated";
}

// Vertex degrees and components, counted here without the code under test.
Shape shape_of(const std::vector<Edge>& edges, std::size_t n) {
  std::vector<std::size_t> degree(n, 0), parent(n);
  for (std::size_t v = 0; v < n; ++v) parent[v] = v;
  const auto root = [&](std::size_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const auto& [i, j] : edges) {
    ++degree[i], ++degree[j];
    parent[root(i)] = root(j);
  }
  std::set<std::size_t> components, open;
  Shape shape{edges.size(), 0, 0, 0, 0};
  for (std::size_t v = 0; v < n; ++v) {
    if (degree[v] == 0) {
      ++shape.isolated;
      continue;
    }
    components.insert(root(v));
    if (degree[v] != 2) open.insert(root(v));
    if (degree[v] == 1) ++shape.open_ends;
  }
  shape.components = components.size();
  shape.closed = components.size() - open.size();
  return shape;
}

struct Output {
  std::vector<Point> points;  // as the file holds them, duplicates included
  std::vector<Edge> edges;
};

Output run(const std::string& algorithm, const fs::path& file) {
  Output result{geometry::read_point_file(file).points, {}};
  result.edges = reconstruct(*find_algorithm(algorithm), result.points).edges;
  return result;
}

#define SKIP_WITHOUT(folder) \
  if (!fs::is_directory(kSharedData / folder)) GTEST_SKIP() << (kSharedData / folder) << " is not here: conformance not checked"

// Every figure: the reference's shape, and its very edges unless listed with a reason.
void expect_conformance(const std::string& algorithm, const fs::path& folder, const std::string& extension,
                        const std::vector<Reference>& references, const std::set<std::string_view>& differing) {
  std::size_t identical = 0;
  for (const Reference& reference : references) {
    SCOPED_TRACE(algorithm + " on " + std::string(reference.figure));
    const Output result = run(algorithm, folder / (std::string(reference.figure) + extension));
    const Shape ours = shape_of(result.edges, result.points.size());
    const Shape theirs{reference.edges, reference.components, reference.closed, reference.open_ends, reference.isolated};
    const bool same = edge_hash(result.edges) == reference.edge_hash;
    identical += same;
    if (differing.contains(reference.figure)) {
      EXPECT_FALSE(same) << "now identical to the reference: take it off the list of differences";
    } else {
      EXPECT_TRUE(same) << "edges differ from the reference program's";
      EXPECT_EQ(ours, theirs);
    }
  }
  EXPECT_EQ(identical, references.size() - differing.size());
}

// The figures whose picture is one closed curve (with, in Fig2c and Fig6e, outliers left
// isolated). The Crawl paper's body is not readable here, so they were picked from a
// drawing of each point set (all 38, side by side) and confirmed against the authors'
// Crawl program, whose output on each is one closed cycle: the same twelve by both.
const std::set<std::string_view> kOneClosedCurve = {"Fig2b", "Fig2c", "Fig2e", "Fig4c", "Fig4d", "Fig4e",
                                                   "Fig5a", "Fig5b", "Fig5f", "Fig6c", "Fig6d", "Fig6e"};

// Recorded from amaldevp/Crawl_through_Neighbors, Crawl.cpp (CGAL 5.5, g++ 12).
const std::vector<Reference> kCrawlReferences = {
      {"Fig1", 368, 5, 5, 0, 0, 0x03fc5320683e6105u},
      {"Fig3", 38, 2, 1, 2, 0, 0x73f0249409e0587cu},
      {"Fig7", 625, 7, 7, 0, 0, 0x65bf479ed9844865u},
      {"Fig8", 292, 4, 4, 0, 0, 0xa868f209df551c1fu},
      {"Fig9", 1025, 6, 6, 0, 2, 0x5f5a197e59a636f7u},
      {"Fig10", 240, 4, 4, 0, 0, 0x468fc5965882d0f3u},
      {"Fig2a", 166, 1, 0, 2, 0, 0x9417e68e2584e09au},
      {"Fig2b", 150, 1, 1, 0, 0, 0x80c9ba36faa8e641u},
      {"Fig2c", 177, 1, 1, 0, 5, 0xe541c8a1630688adu},
      {"Fig2d", 96, 2, 2, 0, 0, 0x7d9fd615050e3bbdu},
      {"Fig2e", 16, 1, 1, 0, 0, 0x88cd241a1eaf2b75u},
      {"Fig2f", 393, 7, 7, 0, 0, 0x182c57aec133bd7bu},
      {"Fig4a", 91, 2, 2, 0, 0, 0x890f664128c10295u},
      {"Fig4b", 178, 2, 2, 0, 0, 0x825985bbbeba69c5u},
      {"Fig4c", 365, 1, 1, 0, 0, 0x6aa570a10f5d7881u},
      {"Fig4d", 298, 1, 1, 0, 0, 0xdca24f078fda5fdfu},
      {"Fig4e", 244, 1, 1, 0, 0, 0xa2c2084d17070acbu},
      {"Fig4f", 134, 2, 2, 0, 0, 0x530cc82ffe180ee7u},
      {"Fig4g", 283, 3, 3, 0, 0, 0xf123f9b9e31ffa19u},
      {"Fig4h", 189, 2, 2, 0, 0, 0xbe3d0e516e39faebu},
      {"Fig4i", 300, 4, 4, 0, 0, 0x986f9e785fc0f365u},
      {"Fig4j", 225, 3, 3, 0, 0, 0x435b3288f687ea11u},
      {"Fig4k", 261, 4, 4, 0, 0, 0x0a0ea0f4c0ae4f09u},
      {"Fig4l", 348, 6, 6, 0, 0, 0xcdd657e4f6e9dbf3u},
      {"Fig5a", 48, 1, 1, 0, 0, 0x7adbcc354cbae79fu},
      {"Fig5b", 177, 1, 1, 0, 0, 0x28baaf6f938f5eb9u},
      {"Fig5c", 164, 4, 4, 0, 0, 0x46848214ad6b58e9u},
      {"Fig5d", 377, 9, 9, 0, 0, 0x79e394ce1318804fu},
      {"Fig5e", 306, 6, 6, 0, 0, 0xcd4949d2fa62c601u},
      {"Fig5f", 20, 1, 1, 0, 0, 0x6df6c46b35b6bacdu},
      {"Fig6a", 242, 3, 0, 6, 0, 0x1e3a760cda2ad75bu},
      {"Fig6b", 277, 2, 0, 4, 0, 0xa25db56c0e4a6f9cu},
      {"Fig6c", 125, 1, 1, 0, 0, 0x355977bf7882a86bu},
      {"Fig6d", 121, 1, 1, 0, 0, 0xf77671094dfc7e63u},
      {"Fig6e", 52, 1, 1, 0, 10, 0x68653f2df5f83a19u},
      {"Fig6f", 53, 2, 1, 2, 28, 0x17f5065570809d92u},
      {"Fig12a", 90, 2, 2, 0, 0, 0xf7121b20d45c80adu},
      {"Fig12b", 119, 2, 1, 2, 0, 0x9fe39149220f6b4eu},
};

// Recorded from amaldevp/Peeling_the_Longest, Reconstruct/reconstruct.cpp, run as its
// README says (input 0 then 2: the default peeling).
const std::vector<Reference> kPeelReferences = {
      {"Fig1", 364, 7, 3, 8, 0, 0x3d4fd3b647714f16u},
      {"Fig3", 38, 2, 1, 2, 0, 0x73f0249409e0587cu},
      {"Fig7", 622, 8, 5, 6, 0, 0xa238cf5b8c1cefcau},
      {"Fig8", 292, 4, 4, 0, 0, 0xa868f209df551c1fu},
      {"Fig9", 1012, 14, 2, 24, 3, 0xa9dca881a2be4f72u},
      {"Fig10", 237, 5, 2, 6, 0, 0xe8605b4338a929f4u},
      {"Fig2a", 166, 1, 0, 2, 0, 0x9417e68e2584e09au},
      {"Fig2b", 150, 1, 1, 0, 0, 0x80c9ba36faa8e641u},
      {"Fig2c", 177, 1, 1, 0, 5, 0xe541c8a1630688adu},
      {"Fig2d", 96, 2, 2, 0, 0, 0x7d9fd615050e3bbdu},
      {"Fig2e", 15, 1, 0, 2, 0, 0xbb9e829bbf5c358du},
      {"Fig2f", 393, 7, 7, 0, 0, 0x182c57aec133bd7bu},
      {"Fig4a", 91, 2, 2, 0, 0, 0x890f664128c10295u},
      {"Fig4b", 178, 2, 2, 0, 0, 0x825985bbbeba69c5u},
      {"Fig4c", 365, 1, 1, 0, 0, 0x6aa570a10f5d7881u},
      {"Fig4d", 298, 1, 1, 0, 0, 0xdca24f078fda5fdfu},
      {"Fig4e", 244, 1, 1, 0, 0, 0xa2c2084d17070acbu},
      {"Fig4f", 134, 2, 2, 0, 0, 0x530cc82ffe180ee7u},
      {"Fig4g", 283, 3, 3, 0, 0, 0xf123f9b9e31ffa19u},
      {"Fig4h", 188, 2, 1, 2, 0, 0x3b1d0e5d1f54bbb9u},
      {"Fig4i", 300, 4, 4, 0, 0, 0x986f9e785fc0f365u},
      {"Fig4j", 225, 3, 3, 0, 0, 0x435b3288f687ea11u},
      {"Fig4k", 261, 4, 4, 0, 0, 0x0a0ea0f4c0ae4f09u},
      {"Fig4l", 348, 6, 6, 0, 0, 0xcdd657e4f6e9dbf3u},
      {"Fig5a", 48, 1, 1, 0, 0, 0x7adbcc354cbae79fu},
      {"Fig5b", 177, 1, 1, 0, 0, 0x28baaf6f938f5eb9u},
      {"Fig5c", 163, 4, 3, 2, 0, 0xc85999133656fda8u},
      {"Fig5d", 366, 15, 4, 22, 0, 0x0cc0db96517e8e20u},
      {"Fig5e", 303, 6, 3, 6, 0, 0x72feda8f1b6bb58bu},
      {"Fig5f", 18, 2, 0, 4, 0, 0xe8adda78bec2809bu},
      {"Fig6a", 240, 4, 0, 8, 1, 0x98e4589e61451ea7u},
      {"Fig6b", 275, 4, 0, 8, 0, 0xc8404b10bc1dd23fu},
      {"Fig6c", 124, 2, 1, 2, 0, 0x74a3764600864980u},
      {"Fig6d", 120, 1, 0, 2, 0, 0x6febb97d65631bdeu},
      {"Fig6e", 54, 3, 1, 4, 6, 0x399c5f143d96e864u},
      {"Fig6f", 57, 5, 0, 11, 20, 0x3411db1b85989ec4u},
      {"Fig12a", 85, 5, 0, 10, 0, 0x7c78d24c2f2ee93du},
      {"Fig12b", 119, 2, 1, 2, 0, 0xa906b6bc5ce6eebeu},
};

const fs::path kCrawlFigures = kSharedData / "crawl";

// Crawl differs where the authors' program meets a tie that ours decides otherwise (Fig5e's
// exact tie between two seed edges of length 9 now goes their way: ours sees the points
// sorted by coordinates, as every edges_on_input algorithm does):
//   Fig6f: at point 48, edges of 13.396794165 and 13.396794171 are equal as floats; theirs
//          grows to 67, ours to the nearer 55, and the rest of the crawl follows;
//   Fig10: seed edges 47-48 (9.9647265199) and 74-75 (9.9647265364), equal as floats;
//          theirs seeds 74-75 first and crawls through 44..52 in one curve, ours seeds
//          47-48 and closes a small loop 45..50 apart.
TEST(Conformance, CrawlMatchesTheAuthorsProgramOnTheirFigures) {
  SKIP_WITHOUT("crawl");
  expect_conformance("crawl", kCrawlFigures, ".txt", kCrawlReferences, {"Fig6f", "Fig10"});
}

// Peel differs on three figures, each a float32 tie in the authors' code between two
// lengths that differ in the ninth digit (ours compares them exactly):
//   Fig6f: at point 48, 48-55 (13.396794165) and 48-67 (13.396794171): theirs keeps 48-67;
//   Fig9:  triangle 868-872-873, sides 9.833653279 and 9.833653324: theirs deletes 868-873;
//   Fig12a: triangle 8-9-10, sides 33.07632846 and 33.07632852: theirs swaps 8-10 for 7-8.
TEST(Conformance, PeelMatchesTheAuthorsProgramOnTheirFigures) {
  SKIP_WITHOUT("crawl");
  expect_conformance("peel", kCrawlFigures, ".txt", kPeelReferences, {"Fig6f", "Fig9", "Fig12a"});
}

// Recorded from stefango74/hnn-crust-sgp16 (src/Reconstruct2D.cpp, unchanged, on Debian's
// libann; its GLUT viewer replaced by a driver that keeps its file loader): on its own
// point sets, bundled in data/hnncrust/ (family.gtn, a grid whose neighbours tie in its
// float coordinates, is left out), and on the Crawl figures.
const std::vector<Reference> kHnnCrustOwnReferences = {
      {"crocodile-conf", 129, 2, 2, 0, 0, 0xbc05d48287257fcfu},
      {"mushroom", 53, 6, 0, 12, 0, 0xc1c6181212ebb9c2u},
      {"ventilator", 184, 13, 3, 20, 0, 0x8f9ee0229024bdc0u},
};
const std::vector<Reference> kHnnCrustReferences = {
      {"Fig1", 363, 7, 2, 10, 0, 0x86b965ab8c162f6bu},
      {"Fig3", 38, 2, 1, 2, 0, 0x73f0249409e0587cu},
      {"Fig7", 622, 8, 5, 6, 0, 0xa238cf5b8c1cefcau},
      {"Fig8", 291, 4, 3, 2, 0, 0x7c2f60f2140a0134u},
      {"Fig9", 1007, 18, 2, 32, 4, 0x411f335a8e4fe727u},
      {"Fig10", 233, 8, 2, 12, 1, 0x9eabd3fde5e61ff0u},
      {"Fig2a", 166, 1, 0, 2, 0, 0x9417e68e2584e09au},
      {"Fig2b", 150, 1, 1, 0, 0, 0x80c9ba36faa8e641u},
      {"Fig2c", 177, 1, 1, 0, 5, 0xe541c8a1630688adu},
      {"Fig2d", 96, 2, 2, 0, 0, 0x7d9fd615050e3bbdu},
      {"Fig2e", 15, 1, 0, 2, 0, 0xbb9e829bbf5c358du},
      {"Fig2f", 393, 7, 7, 0, 0, 0x182c57aec133bd7bu},
      {"Fig4a", 91, 2, 2, 0, 0, 0x890f664128c10295u},
      {"Fig4b", 178, 2, 2, 0, 0, 0x825985bbbeba69c5u},
      {"Fig4c", 365, 1, 1, 0, 0, 0x6aa570a10f5d7881u},
      {"Fig4d", 298, 1, 1, 0, 0, 0xdca24f078fda5fdfu},
      {"Fig4e", 244, 1, 1, 0, 0, 0xa2c2084d17070acbu},
      {"Fig4f", 134, 2, 2, 0, 0, 0x530cc82ffe180ee7u},
      {"Fig4g", 283, 3, 3, 0, 0, 0xf123f9b9e31ffa19u},
      {"Fig4h", 188, 2, 1, 2, 0, 0x3b1d0e5d1f54bbb9u},
      {"Fig4i", 300, 4, 4, 0, 0, 0x986f9e785fc0f365u},
      {"Fig4j", 225, 3, 3, 0, 0, 0x435b3288f687ea11u},
      {"Fig4k", 261, 4, 4, 0, 0, 0x0a0ea0f4c0ae4f09u},
      {"Fig4l", 348, 6, 6, 0, 0, 0xcdd657e4f6e9dbf3u},
      {"Fig5a", 47, 1, 0, 2, 0, 0xebd8b3228371ead6u},
      {"Fig5b", 177, 1, 1, 0, 0, 0x28baaf6f938f5eb9u},
      {"Fig5c", 163, 4, 3, 2, 0, 0xc85999133656fda8u},
      {"Fig5d", 366, 15, 4, 22, 0, 0x0cc0db96517e8e20u},
      {"Fig5e", 302, 7, 3, 8, 0, 0xb9937b22c07c771au},
      {"Fig5f", 18, 2, 0, 4, 0, 0xe8adda78bec2809bu},
      {"Fig6a", 240, 4, 0, 8, 1, 0x98e4589e61451ea7u},
      {"Fig6b", 275, 4, 0, 8, 0, 0xc8404b10bc1dd23fu},
      {"Fig6c", 122, 4, 1, 6, 0, 0x422b51c7a3acc40du},
      {"Fig6d", 120, 1, 0, 2, 0, 0x6febb97d65631bdeu},
      {"Fig6e", 52, 2, 0, 4, 8, 0x5fe1c31fa4011c08u},
      {"Fig6f", 59, 9, 0, 18, 14, 0xc3619dcdcca95981u},
      {"Fig12a", 85, 5, 0, 10, 0, 0xf75772c137e054e1u},
      {"Fig12b", 119, 2, 1, 2, 0, 0xa906b6bc5ce6eebeu},
};

TEST(Conformance, HnnCrustMatchesTheAuthorsProgramOnTheirPointSets) {
  expect_conformance("hnn-crust", fs::path(CURVEBENCH_SOURCE_DIR) / "data" / "hnncrust", ".p2d", kHnnCrustOwnReferences,
                     {});
}

// HNN-Crust differs on two Crawl figures, ours having more edges:
//   Fig5e: from point 153, points 154 and 237 are both at squared distance 324; theirs (ANN)
//          returns 237 first, so 153 and 154 never pick each other; ours takes 154;
//   Fig9:  one point stored three times; theirs does not merge copies, each copy's nearest
//          is another at distance 0, the half-neighbour test fails and the curve breaks.
TEST(Conformance, HnnCrustMatchesTheAuthorsProgramOnTheCrawlFigures) {
  SKIP_WITHOUT("crawl");
  expect_conformance("hnn-crust", kCrawlFigures, ".txt", kHnnCrustReferences, {"Fig5e", "Fig9"});
}

// The survey's claim checked on the figures, not on the reference: a one-curve figure
// gives one closed cycle through every point the reference program did not leave isolated
// as an outlier.
TEST(Conformance, CrawlClosesEveryOneCurveFigure) {
  SKIP_WITHOUT("crawl");
  for (const Reference& reference : kCrawlReferences) {
    if (!kOneClosedCurve.contains(reference.figure)) continue;
    SCOPED_TRACE(reference.figure);
    const Output result = run("crawl", kCrawlFigures / (std::string(reference.figure) + ".txt"));
    const Shape shape = shape_of(result.edges, result.points.size());
    EXPECT_EQ(shape.components, 1u);
    EXPECT_EQ(shape.closed, 1u);
    EXPECT_EQ(shape.isolated, reference.isolated);
    EXPECT_EQ(shape.edges + shape.isolated, result.points.size());
  }
}

// Peel on the same figures: closed on seven; open on five, as the authors' program leaves
// them too, whose sampling is sparse against the curve's bends (Fig2e, Fig5f: 16 and 20
// points) or whose corners are sharp (the stars Fig6c, Fig6d; Fig6e, with outliers). Peel
// claims closed curves only under its own sampling condition, which these do not meet.
TEST(Conformance, PeelClosesTheOneCurveFiguresTheAuthorsProgramCloses) {
  SKIP_WITHOUT("crawl");
  const std::set<std::string_view> open_in_theirs_too = {"Fig2e", "Fig5f", "Fig6c", "Fig6d", "Fig6e"};
  for (const Reference& reference : kPeelReferences) {
    if (!kOneClosedCurve.contains(reference.figure)) continue;
    SCOPED_TRACE(reference.figure);
    const Output result = run("peel", kCrawlFigures / (std::string(reference.figure) + ".txt"));
    const Shape shape = shape_of(result.edges, result.points.size());
    if (open_in_theirs_too.contains(reference.figure)) {
      EXPECT_NE(reference.open_ends, 0u);
      EXPECT_NE(shape.open_ends, 0u);
    } else {
      EXPECT_EQ(shape.components, 1u);
      EXPECT_EQ(shape.closed, 1u);
      EXPECT_EQ(shape.edges + shape.isolated, result.points.size());
    }
  }
}

}  // namespace
}  // namespace curvebench::algorithms
