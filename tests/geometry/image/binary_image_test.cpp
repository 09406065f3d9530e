#include "geometry/image/binary_image.h"

#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <CGAL/Polygon_2_algorithms.h>

#include <cmath>
#include <numbers>
#include <sstream>

#include "geometry/curves/analytic_curves.h"
#include "geometry/curves/polyline_curve.h"
#include "tests/support/expect_parse_error.h"
#include "tests/support/temporary_directory.h"

namespace curvebench::geometry {
namespace {

using testing::BadInput;
using testing::expect_parse_error;

// 10 x 3 (not a multiple of 8, so P4 rows are padded): an object of white pixels.
const char* const picture[] = {
    "..##....#.",
    ".####..##.",
    "#....#...#",
};

Binary_image picture_image() {
  Binary_image image{10, 3, {}};
  for (const char* row : picture)
    for (int x = 0; x < 10; ++x) image.pixels.push_back(row[x] == '#');
  return image;
}

// The picture in each netpbm format, written here independently of the reader.
std::string as_p1() {  // PBM's 1 is black: the object is the 0 bits
  std::string text = "P1\n# a comment in the header\n10 3\n";
  for (const char* row : picture) {
    for (int x = 0; x < 10; ++x) text += row[x] == '#' ? "0" : "1";  // no separators needed in P1
    text += "  # a comment in the raster\n";
  }
  return text;
}
std::string as_p2(int maxval) {
  std::string text = "P2 10 3\r\n" + std::to_string(maxval) + "\r\n";
  for (const char* row : picture) {
    for (int x = 0; x < 10; ++x) text += std::to_string(row[x] == '#' ? maxval / 2 + 1 : maxval / 2) + " ";
    text += "\r\n";
  }
  return text;
}
std::string as_p4() {
  std::string text = "P4\n10 3\n";
  for (const char* row : picture) {
    unsigned char bytes[2] = {0, 0x3f};  // padding bits are ignored: set them to garbage
    for (int x = 0; x < 10; ++x)
      if (row[x] != '#') bytes[x / 8] |= static_cast<unsigned char>(0x80 >> (x % 8));
    text.append(reinterpret_cast<const char*>(bytes), 2);
  }
  return text;
}
std::string as_p5(int maxval) {
  std::string text = "P5\n10 3 #comment\n" + std::to_string(maxval) + "\n";
  for (const char* row : picture)
    for (int x = 0; x < 10; ++x) {
      const int value = row[x] == '#' ? maxval : 0;
      if (maxval > 255) text += static_cast<char>(value >> 8);
      text += static_cast<char>(value & 0xff);
    }
  return text + "P5 trailing data: the next image of a stream";
}

TEST(Netpbm, EveryFormatReadsTheSamePicture) {
  const Binary_image expected = picture_image();
  EXPECT_EQ(parse_netpbm(as_p1(), "a.pbm"), expected);
  EXPECT_EQ(parse_netpbm(as_p2(255), "a.pgm"), expected);
  EXPECT_EQ(parse_netpbm(as_p2(1), "a.pgm"), expected);  // 1 is above 1 / 2, 0 is not
  EXPECT_EQ(parse_netpbm(as_p2(65535), "a.pgm"), expected);
  EXPECT_EQ(parse_netpbm(as_p4(), "a.pbm"), expected);
  EXPECT_EQ(parse_netpbm(as_p5(255), "a.pgm"), expected);
  EXPECT_EQ(parse_netpbm(as_p5(40000), "a.pgm"), expected);  // two bytes per value
}

TEST(Netpbm, ForegroundIsAboveHalfOfMaxval) {
  // maxval 255: 127 is background, 128 object; maxval 10: 5 background, 6 object.
  const Binary_image image = parse_netpbm("P2 4 1 255 0 127 128 255", "x");
  EXPECT_EQ(image.pixels, (std::vector<std::uint8_t>{0, 0, 1, 1}));
  EXPECT_EQ(parse_netpbm("P2 2 1 10 5 6", "x").pixels, (std::vector<std::uint8_t>{0, 1}));
}

TEST(Netpbm, WritePgmThenReadIsTheSameImage) {
  const testing::TemporaryDirectory directory;
  const Binary_image image = picture_image();
  write_pgm(image, directory.path() / "a.pgm");
  EXPECT_EQ(read_netpbm(directory.path() / "a.pgm"), image);
  const std::string bytes = testing::read_bytes(directory.path() / "a.pgm");
  EXPECT_EQ(bytes.substr(0, 12), "P5\n10 3\n255\n");
  EXPECT_EQ(bytes.size(), 12u + 30u);
  EXPECT_EQ(bytes[12 + 2], '\xff');  // (2, 0) is object: white
  EXPECT_EQ(bytes[12 + 0], '\0');

  const Binary_image empty{0, 0, {}};
  write_pgm(empty, directory.path() / "empty.pgm");
  EXPECT_EQ(read_netpbm(directory.path() / "empty.pgm"), empty);
  EXPECT_THROW(write_pgm(Binary_image{2, 2, {1}}, directory.path() / "bad.pgm"), std::invalid_argument);
}

TEST(Netpbm, ImagesWithoutPixelsTakeNoTime) {
  // 0 x 2^28: valid netpbm, and nothing to walk through row by row.
  const Binary_image image = parse_netpbm("P4 0 268435456\n", "empty.pbm");
  EXPECT_EQ(image.width, 0u);
  EXPECT_EQ(image.height, std::size_t{1} << 28);
  EXPECT_TRUE(image.pixels.empty());
  std::ostringstream written;
  write_pgm(image, written);
  EXPECT_EQ(written.str(), "P5\n0 268435456\n255\n");
  const std::vector<std::vector<Point>> triangle{{Point(0, 0), Point(1, 5), Point(0, 9)}};
  EXPECT_EQ(fill_even_odd(triangle, 0, std::size_t{1} << 28).height, std::size_t{1} << 28);
  expect_parse_error([] { parse_netpbm("P1 0 3 1", "extra.pbm"); }, "extra.pbm", 1, "'1'");
}

TEST(Netpbm, MalformedFilesNameTheLine) {
  const BadInput cases[] = {
      {"empty.pgm", "", 1, "magic number"},
      {"colour.ppm", "P6\n1 1\n255\n\1\2\3", 1, "'P6'"},
      {"text.pgm", "hello", 1, "'he'"},
      {"glued.pgm", "P2x 1 1", 1, "'x'"},
      {"width.pbm", "P1\n2 x\n01", 2, "'x'"},
      {"negative.pgm", "P2\n# size:\n-1 1\n", 3, "'-1'"},
      {"huge.pgm", "P2\n99999999999999999999999 1\n", 2, "'99999999999999999999999'"},
      {"limit.pbm", "P4\n100000 100000\n", 2, "2^28"},
      {"maxval.pgm", "P2\n2 1\n70000\n0 0\n", 3, "'70000'"},
      {"zero.pgm", "P2\n2 1\n0\n0 0\n", 3, "maxval must be"},
      {"value.pgm", "P2\n2 1\n255\n0\n300\n", 5, "'300'"},
      {"real.pgm", "P2\n2 1\n255\n0 1.5\n", 4, "'1.5'"},
      {"digit.pbm", "P1\n2 2\n0 1\n1 2\n", 4, "'2'"},
      {"short.pbm", "P1\n2 2\n0 1\n1\n", 4, "ends after 3 of 2 x 2"},
      {"long.pbm", "P1\n2 1\n0 1\n\n1\n", 5, "'1'"},
      {"noheight.pbm", "P1 2", 1, "height"},
      {"noraster.pgm", "P5\n2 1\n255", 3, "before the raster"},
      {"truncated.pgm", "P5\n2 2\n255\n\1", 4, "1 bytes"},
      {"above.pgm", "P5\n2 1\n200\n\xff\x01", 4, "above maxval 200"},
      {"p4.pbm", "P4\n9 2\n\1\2\3", 3, "need 4"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.file_name);
    expect_parse_error([&] { parse_netpbm(c.text, c.file_name); }, c.file_name, c.line, c.mention);
  }
  const testing::TemporaryDirectory directory;
  expect_parse_error([&] { read_netpbm(directory.path() / "missing.pgm"); }, (directory.path() / "missing.pgm").string(), 0,
                     "cannot open");
}

TEST(Netpbm, ArbitraryBytesParseOrThrowParseError) {
  EXPECT_TRUE(rc::check("random bytes after a valid magic number", [] {
    const std::string magic = *rc::gen::element<std::string>("P1", "P2", "P4", "P5", "P1 3 2", "P2 3 2 7", "P5 2 2 300\n");
    const std::string rest = *rc::gen::container<std::string>(rc::gen::element(' ', '0', '1', '7', '#', '\n', '\xff', 'a'));
    try {
      const Binary_image image = parse_netpbm(magic + rest, "random");
      RC_ASSERT(image.pixels.size() == image.width * image.height);
    } catch (const ParseError& error) {
      RC_ASSERT(std::string(error.what()).starts_with("random:"));
    }
  }));
}

// ---- fill_even_odd and rasterize --------------------------------------------------

// The even-odd rule pixel by pixel, straight from its definition: edges crossing the
// horizontal line through the centre (half-open in y) with the centre strictly left.
bool inside_by_crossings(const std::vector<std::vector<Point>>& polygons, const Point& c) {
  bool inside = false;
  for (const auto& polygon : polygons)
    for (std::size_t k = 0; k < polygon.size(); ++k) {
      const Point& a = polygon[k];
      const Point& b = polygon[(k + 1) % polygon.size()];
      const bool a_below = a.y() <= c.y(), b_below = b.y() <= c.y();
      if (a_below == b_below) continue;  // both on one side of the line (horizontal edges too)
      const Point& lower = a_below ? a : b;
      const Point& upper = a_below ? b : a;
      if (CGAL::orientation(lower, upper, c) == CGAL::LEFT_TURN) inside = !inside;
    }
  return inside;
}

Point centre(std::size_t x, std::size_t y) { return {x + 0.5, y + 0.5}; }

TEST(FillEvenOdd, AgreesWithTheCrossingRuleAtEveryPixelCentre) {
  EXPECT_TRUE(rc::check("random polygons, vertices on a half-pixel grid or anywhere", [] {
    const std::size_t width = *rc::gen::inRange<std::size_t>(0, 24), height = *rc::gen::inRange<std::size_t>(0, 24);
    // Half-integer vertices put centres exactly on edges and vertices on centre rows.
    const bool on_grid = *rc::gen::arbitrary<bool>();
    const auto coordinate = [&] {
      return on_grid ? *rc::gen::inRange(-4, 56) / 2.0 : *rc::gen::inRange(-4000, 28000) / 997.0;
    };
    std::vector<std::vector<Point>> polygons(*rc::gen::inRange(1, 4));
    for (auto& polygon : polygons) {
      polygon.resize(*rc::gen::inRange(0, 9));
      for (Point& p : polygon) p = Point(coordinate(), coordinate());
    }
    const Binary_image image = fill_even_odd(polygons, width, height);
    RC_ASSERT(image.width == width && image.height == height && image.pixels.size() == width * height);
    for (std::size_t y = 0; y < height; ++y)
      for (std::size_t x = 0; x < width; ++x) RC_ASSERT(image.at(x, y) == inside_by_crossings(polygons, centre(x, y)));
  }));
}

TEST(FillEvenOdd, OfASimplePolygonIsItsInteriorByCgal) {
  EXPECT_TRUE(rc::check("random star-shaped polygons against CGAL::bounded_side_2", [] {
    const int n = *rc::gen::inRange(3, 40);
    std::vector<Point> polygon;
    for (int k = 0; k < n; ++k) {
      const double angle = 2 * std::numbers::pi * (k + *rc::gen::inRange(0, 900) / 1000.0) / n;
      const double radius = *rc::gen::inRange(10, 150) / 10.0;
      polygon.emplace_back(16 + radius * std::cos(angle), 16 + radius * std::sin(angle));
    }
    const Binary_image image = fill_even_odd({polygon}, 32, 32);
    for (std::size_t y = 0; y < 32; ++y)
      for (std::size_t x = 0; x < 32; ++x) {
        const auto side = CGAL::bounded_side_2(polygon.begin(), polygon.end(), centre(x, y), Kernel());
        if (side != CGAL::ON_BOUNDARY) RC_ASSERT(image.at(x, y) == (side == CGAL::ON_BOUNDED_SIDE));
      }
  }));
}

TEST(FillEvenOdd, HolesAndOverlapsFollowTheEvenOddRule) {
  const std::vector<Point> outer{{1, 1}, {9, 1}, {9, 9}, {1, 9}}, hole{{3, 3}, {7, 3}, {7, 7}, {3, 7}};
  const Binary_image image = fill_even_odd({outer, hole}, 10, 10);
  EXPECT_TRUE(image.at(2, 2));
  EXPECT_FALSE(image.at(5, 5));
  EXPECT_FALSE(image.at(0, 0));
  EXPECT_EQ(std::count(image.pixels.begin(), image.pixels.end(), 1), 64 - 16);
  const std::vector<Point> not_finite{{0, 0}, {NAN, 1}, {1, 1}};
  EXPECT_THROW(fill_even_odd({not_finite}, 4, 4), std::invalid_argument);
}

TEST(Rasterize, ACircleOfRadiusRPixelsHasAboutPiRSquaredPixels) {
  for (const std::size_t resolution : {8, 29, 100, 301}) {
    SCOPED_TRACE(resolution);
    Raster_frame frame;
    const Binary_image image = rasterize(circle(1), resolution, &frame);
    EXPECT_EQ(image.width, resolution);
    EXPECT_EQ(image.height, resolution);
    const double r = frame.scale;  // the circle's radius in pixels
    EXPECT_NEAR(r, (resolution - 4) / 2.0, 1e-3 * r);
    const Point c = frame.to_image(Point(0, 0));
    EXPECT_NEAR(c.x(), resolution / 2.0, 1e-9 * resolution);
    std::size_t area = 0;
    for (std::size_t y = 0; y < image.height; ++y)
      for (std::size_t x = 0; x < image.width; ++x) {
        area += image.at(x, y);
        // The polygon is within 0.05 pixel of the circle: beyond 0.1 the answer is known.
        const double d = std::sqrt(CGAL::squared_distance(centre(x, y), c));
        if (d < r - 0.1) {
          EXPECT_TRUE(image.at(x, y)) << x << ", " << y;
        } else if (d > r + 0.1) {
          EXPECT_FALSE(image.at(x, y)) << x << ", " << y;
        }
      }
    EXPECT_NEAR(static_cast<double>(area), std::numbers::pi * r * r, 2 * std::numbers::pi * r / 4);  // a quarter of the perimeter
  }
}

// The distance from c to the polygon's boundary, in double (only to skip the centres a
// floating-point construction could move across the boundary).
double distance_to_boundary(const std::vector<Point>& polygon, const Point& c) {
  double d = INFINITY;
  for (std::size_t k = 0; k < polygon.size(); ++k)
    d = std::min(d, std::sqrt(CGAL::squared_distance(Kernel::Segment_2(polygon[k], polygon[(k + 1) % polygon.size()]), c)));
  return d;
}

TEST(Rasterize, APolygonCurveIsFilledAsCgalSaysAtEveryCentre) {
  EXPECT_TRUE(rc::check("random star-shaped polygon curves", [] {
    const int n = *rc::gen::inRange(3, 25);
    GroundTruth truth;
    for (int k = 0; k < n; ++k) {
      const double angle = 2 * std::numbers::pi * (k + *rc::gen::inRange(0, 900) / 1000.0) / n;
      const double radius = *rc::gen::inRange(1, 100) / 7.0;
      truth.points.emplace_back(3 + radius * std::cos(angle), -2 + radius * std::sin(angle));
      truth.edges.emplace_back(k, (k + 1) % n);
    }
    const std::size_t resolution = *rc::gen::inRange<std::size_t>(8, 80);
    Raster_frame frame;
    const Binary_image image = rasterize(polyline_curve(truth), resolution, &frame);
    RC_ASSERT(std::max(image.width, image.height) == resolution);
    std::vector<Point> polygon;
    for (const Point& p : truth.points) polygon.push_back(frame.to_image(p));
    for (std::size_t y = 0; y < image.height; ++y)
      for (std::size_t x = 0; x < image.width; ++x) {
        if (distance_to_boundary(polygon, centre(x, y)) < 1e-6) continue;
        const bool inside = CGAL::bounded_side_2(polygon.begin(), polygon.end(), centre(x, y), Kernel()) == CGAL::ON_BOUNDED_SIDE;
        RC_ASSERT(image.at(x, y) == inside);
      }
  }));
}

TEST(Rasterize, KeepsTheCurveUprightWithinTheMargin) {
  // A triangle with its apex up: the top object row is the narrowest; 2 pixels of margin.
  const GroundTruth triangle{{Point(0, 0), Point(4, 0), Point(2, 2)}, {{0, 1}, {1, 2}, {2, 0}}};
  Raster_frame frame;
  const Binary_image image = rasterize(polyline_curve(triangle), 44, &frame);
  EXPECT_EQ(image.width, 44u);
  EXPECT_EQ(image.height, 24u);  // 2 x 40 / 4 + 4
  const auto row_count = [&](std::size_t y) {
    std::size_t count = 0;
    for (std::size_t x = 0; x < image.width; ++x) count += image.at(x, y);
    return count;
  };
  for (std::size_t y : {0, 1, 22, 23}) EXPECT_EQ(row_count(y), 0u) << y;
  EXPECT_LT(row_count(3), row_count(20));
  EXPECT_GT(row_count(20), 30u);
  const Point apex = frame.to_curve(frame.to_image(Point(2, 2)).x(), frame.to_image(Point(2, 2)).y());
  EXPECT_NEAR(apex.x(), 2, 1e-12);
  EXPECT_NEAR(apex.y(), 2, 1e-12);
  EXPECT_NEAR(frame.to_image(Point(2, 2)).y(), 2, 1e-9);  // the top of the box, 2 pixels down
}

TEST(Rasterize, TwoNestedCirclesMakeAnAnnulus) {
  Curve rings = circle(2);
  rings.components.push_back(Curve_component({std::make_shared<Circular_arc>(Point(0, 0), 1, 0, 2 * std::numbers::pi)}, true));
  const Binary_image image = rasterize(rings, 64);
  EXPECT_FALSE(image.at(32, 32));
  EXPECT_TRUE(image.at(32, 32 - 22));  // radius 1.5 of 2 at 30 pixels per 2
  EXPECT_FALSE(image.at(0, 0));
}

TEST(Rasterize, RejectsOpenCurvesAndBadResolutions) {
  const GroundTruth open{{Point(0, 0), Point(1, 0), Point(1, 1)}, {{0, 1}, {1, 2}}};
  EXPECT_THROW(rasterize(polyline_curve(open), 100), std::invalid_argument);
  EXPECT_THROW(rasterize(circle(1), 7), std::invalid_argument);
  EXPECT_THROW(rasterize(circle(1), 16385), std::invalid_argument);
  EXPECT_THROW(rasterize(Curve{"nothing", {}}, 100), std::invalid_argument);
}

}  // namespace
}  // namespace curvebench::geometry
