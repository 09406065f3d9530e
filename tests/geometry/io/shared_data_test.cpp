// Every point file of the public data sets (../shared/data beside the repository, described in its
// README.md) and of the copies bundled in data/, checked against oracles that share no
// code with the reader: lines split on every CR and every LF, numbers parsed by
// std::istringstream (strtod) instead of std::from_chars.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <locale>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "geometry/io/point_io.h"
#include "tests/support/temporary_directory.h"

namespace curvebench::geometry {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;

const fs::path kSharedData = CURVEBENCH_SHARED_DATA_DIR;
const fs::path kBundledData = fs::path(CURVEBENCH_SOURCE_DIR) / "data";
const char* const kPointFolders[] = {"crawl", "hnncrust", "stretchdenoise"};

#define SKIP_WITHOUT_SHARED_DATA() \
  if (!fs::is_directory(kSharedData)) GTEST_SKIP() << kSharedData << " is not here"

struct OracleLine {
  std::size_t number;  // 1-based
  std::string text;
};

// Lines holding anything but spaces and tabs, numbered by counting every CR and every
// LF as a line end: right for files that never use CRLF, which the callers check.
std::vector<OracleLine> non_blank_lines(const std::string& bytes) {
  std::vector<OracleLine> lines;
  std::size_t number = 1;
  std::string current;
  for (const char c : bytes + '\n') {
    if (c == '\r' || c == '\n') {
      if (current.find_first_not_of(" \t") != std::string::npos) lines.push_back({number, current});
      current.clear();
      ++number;
    } else {
      current += c;
    }
  }
  return lines;
}

// The same count for any file: a CRLF adds one empty line, which is not counted.
std::size_t oracle_point_count(const fs::path& file) {
  const std::size_t header = file.extension() == ".gtn" ? 1 : 0;
  return non_blank_lines(read_bytes(file)).size() - header;
}

std::vector<double> numbers_on(const std::string& line) {
  std::istringstream in(line);
  in.imbue(std::locale::classic());
  std::vector<double> numbers;
  for (double x; in >> x;) numbers.push_back(x);
  return numbers;
}

std::vector<fs::path> point_files_in(const fs::path& folder) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.path().extension() != ".svg") files.push_back(entry.path());
  }
  std::ranges::sort(files);
  return files;
}

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

TEST(SharedData, EveryPointFileMatchesAnIndependentReading) {
  SKIP_WITHOUT_SHARED_DATA();
  std::size_t files = 0;
  for (const char* folder : kPointFolders) {
    for (const fs::path& path : point_files_in(kSharedData / folder)) {
      SCOPED_TRACE(path.string());
      ++files;
      const PointFile file = read_point_file(path);
      ASSERT_EQ(file.points.size(), oracle_point_count(path));

      auto lines = non_blank_lines(read_bytes(path));
      const bool triangle = path.extension() == ".gtn";
      if (triangle) lines.erase(lines.begin());  // the header
      for (std::size_t i = 0; i < lines.size(); ++i) {
        std::vector<double> numbers = numbers_on(lines[i].text);
        if (triangle) numbers.erase(numbers.begin());  // the vertex index
        ASSERT_GE(numbers.size(), 2u) << lines[i].text;
        EXPECT_TRUE(same_bits(file.points[i].x(), numbers[0])) << lines[i].text;
        EXPECT_TRUE(same_bits(file.points[i].y(), numbers[1])) << lines[i].text;
        if (!file.values.empty()) {
          EXPECT_TRUE(same_bits(file.values[i], numbers.at(2)));
        }
      }
    }
  }
  EXPECT_EQ(files, 38u + 6u + 24u) << "the README lists 38 + 6 + 24 point files";
}

TEST(SharedData, CrawlLineNumbersFollowOldMacLineEndings) {
  SKIP_WITHOUT_SHARED_DATA();
  for (const fs::path& path : point_files_in(kSharedData / "crawl")) {
    SCOPED_TRACE(path.string());
    const std::string bytes = read_bytes(path);
    ASSERT_NE(bytes.find('\r'), std::string::npos);
    ASSERT_EQ(bytes.find("\r\n"), std::string::npos) << "the oracle needs files without CRLF";
    std::vector<std::size_t> expected;
    for (const OracleLine& line : non_blank_lines(bytes)) expected.push_back(line.number);
    EXPECT_EQ(read_point_file(path).lines, expected);
  }
}

TEST(SharedData, EachGtnHoldsThePointsOfItsP2d) {
  SKIP_WITHOUT_SHARED_DATA();
  for (const fs::path& gtn : point_files_in(kSharedData / "hnncrust")) {
    if (gtn.extension() != ".gtn") continue;
    SCOPED_TRACE(gtn.string());
    // family.p2d lives in stretchdenoise/, the others beside their .gtn.
    fs::path p2d = fs::path(gtn).replace_extension(".p2d");
    if (!fs::exists(p2d)) p2d = kSharedData / "stretchdenoise" / p2d.filename();
    ASSERT_TRUE(fs::exists(p2d));
    const auto a = read_point_file(gtn).points;
    const auto b = read_point_file(p2d).points;
    ASSERT_EQ(a.size(), b.size());
    EXPECT_TRUE(std::ranges::equal(a, b)) << "same points in the same order";
  }
}

TEST(BundledData, FilesAreExactCopiesOfTheSharedOriginals) {
  SKIP_WITHOUT_SHARED_DATA();
  std::size_t files = 0;
  for (const char* folder : {"svg", "stretchdenoise", "hnncrust"}) {  // sample2d/ is ours: made from svg/
    for (const auto& entry : fs::directory_iterator(kSharedData / folder)) {
      SCOPED_TRACE(entry.path().string());
      ++files;
      const fs::path copy = kBundledData / folder / entry.path().filename();
      ASSERT_TRUE(fs::exists(copy));
      EXPECT_EQ(read_bytes(copy), read_bytes(entry.path()));
    }
  }
  EXPECT_GT(files, 0u);
  EXPECT_FALSE(fs::exists(kBundledData / "crawl")) << "its licence forbids copying it";
}

// Rows of data/README.md: | `folder/file` | format | points | category | source |
TEST(BundledData, ManifestListsEveryPointFileWithItsPointCount) {
  const std::string manifest = read_bytes(kBundledData / "README.md");
  const std::regex row(R"(\|\s*`([^`]+)`\s*\|[^|\n]*\|\s*(\d+|-)\s*\|)");
  std::vector<fs::path> listed;
  for (std::sregex_iterator it(manifest.begin(), manifest.end(), row), end; it != end; ++it) {
    const fs::path path = kBundledData / (*it)[1].str();
    SCOPED_TRACE(path.string());
    ASSERT_TRUE(fs::exists(path));
    listed.push_back(path);
    if (path.extension() == ".svg") continue;
    const std::size_t count = std::stoul((*it)[2].str());
    EXPECT_EQ(count, oracle_point_count(path));
    EXPECT_EQ(count, read_point_file(path).points.size());
  }
  for (const char* folder : {"svg", "sample2d", "stretchdenoise", "hnncrust"}) {
    for (const auto& entry : fs::directory_iterator(kBundledData / folder)) {
      EXPECT_NE(std::ranges::find(listed, entry.path()), listed.end())
          << entry.path() << " is missing from the manifest";
    }
  }
}

}  // namespace
}  // namespace curvebench::geometry
