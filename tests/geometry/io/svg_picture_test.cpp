#include "geometry/io/svg_picture.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <optional>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/support/finite_double.h"
#include "tests/support/temporary_directory.h"

namespace curvebench::geometry {
namespace {

struct Element {
  std::string name;
  std::map<std::string, std::string> attributes;
};

// A small, strict reader of the subset of XML the picture uses, to find what a viewer
// would choke on: one root <svg>, balanced tags, text without raw '<' or stray '&', and
// coordinates that are not finite numbers inside the canvas. It lists the elements with
// their attributes in document order, and the problems it found, one per line.
// A shape of a <path d="...">: a segment "M x1 y1L x2 y2" or a dot "M x yh0".
struct Shape {
  bool dot = false;
  double x1 = 0, y1 = 0, x2 = 0, y2 = 0;  // a dot: at (x1, y1)
};

struct ParsedSvg {
  std::vector<Element> elements;
  std::vector<Shape> shapes;  // of every path, in document order
  double width = 0, height = 0;
  std::string problems;
};

std::optional<double> to_number(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0') return std::nullopt;
  return value;
}

ParsedSvg parse_svg(const std::string& svg) {
  ParsedSvg parsed;
  const auto problem = [&](const std::string& what) { parsed.problems += what + "\n"; };
  if (!svg.starts_with("<svg ")) problem("does not start with <svg: " + svg.substr(0, 20));
  const std::regex tag(R"(<(/?)([a-z]+)((?:\s+[A-Za-z0-9:-]+="[^"<]*")*)\s*(/?)>)");
  const std::regex attribute(R"(([A-Za-z0-9:-]+)="([^"]*)\")");
  const std::regex text_ok(R"(([^<&]|&(amp|lt|gt|quot|apos);)*)");
  std::vector<std::string> open;
  auto rest = svg.cbegin();
  for (std::sregex_iterator it(svg.begin(), svg.end(), tag), end; it != end; ++it) {
    const std::smatch& m = *it;
    if (!std::regex_match(rest, m[0].first, text_ok)) {
      problem("bad text before " + m.str() + ": " + std::string(rest, m[0].first));
    }
    rest = m[0].second;
    if (m[1].length()) {  // closing tag
      if (open.empty() || open.back() != m[2].str()) problem("unbalanced " + m.str());
      if (!open.empty()) open.pop_back();
      continue;
    }
    if (open.empty() && !parsed.elements.empty()) problem("a second root " + m.str());
    Element element{m[2].str(), {}};
    const std::string attributes = m[3].str();
    for (std::sregex_iterator a(attributes.begin(), attributes.end(), attribute), none; a != none;
         ++a) {
      element.attributes[(*a)[1].str()] = (*a)[2].str();
    }
    if (!m[4].length()) open.push_back(element.name);
    parsed.elements.push_back(std::move(element));
  }
  if (!open.empty()) problem("unclosed <" + open.back() + ">");
  if (std::string(rest, svg.cend()) != "\n")
    problem("trailing text " + std::string(rest, svg.cend()));
  if (parsed.elements.empty()) return parsed;
  parsed.width = to_number(parsed.elements[0].attributes["width"]).value_or(-1);
  parsed.height = to_number(parsed.elements[0].attributes["height"]).value_or(-1);
  // Path data: chains "M x yL x yL x y..." (a segment per L) and dots "M x yh0", every
  // coordinate a number on the canvas.
  const std::regex piece(R"(M([^ ]+) ([^LhM]+)(h0|(?:L[^ ]+ [^LM]+)+))");
  const std::regex vertex(R"(L([^ ]+) ([^LM]+))");
  for (const auto& [name, attributes] : parsed.elements) {
    if (name != "path") continue;
    const std::string& d = attributes.count("d") ? attributes.at("d") : std::string();
    std::size_t covered = 0;
    const auto coordinate = [&](const std::string& text, bool x) {
      const std::optional<double> number = to_number(text);
      const double limit = x ? parsed.width : parsed.height;
      if (!number || !std::isfinite(*number) || *number < 0 || *number > limit)
        problem("path coordinate " + text + " is not a number in [0, " + std::to_string(limit) + "]");
      return number.value_or(0);
    };
    for (std::sregex_iterator it(d.begin(), d.end(), piece), none; it != none; ++it) {
      const std::smatch& m = *it;
      if (static_cast<std::size_t>(m.position(0)) != covered) break;
      covered += static_cast<std::size_t>(m.length(0));
      double x = coordinate(m[1].str(), true), y = coordinate(m[2].str(), false);
      if (m[3].str() == "h0") {
        parsed.shapes.push_back({.dot = true, .x1 = x, .y1 = y});
        continue;
      }
      const std::string chain = m[3].str();
      for (std::sregex_iterator v(chain.begin(), chain.end(), vertex), end; v != end; ++v) {
        const double x2 = coordinate((*v)[1].str(), true), y2 = coordinate((*v)[2].str(), false);
        parsed.shapes.push_back({.dot = false, .x1 = x, .y1 = y, .x2 = x2, .y2 = y2});
        x = x2, y = y2;
      }
    }
    if (d.empty() || covered != d.size()) problem("path data not M x yL x y or M x yh0 pieces: " + d);
  }
  return parsed;
}

// The SVG of `picture`, which must be free of problems.
ParsedSvg render(const SvgPicture& picture) {
  std::ostringstream out;
  picture.write(out);
  ParsedSvg parsed = parse_svg(out.str());
  EXPECT_EQ(parsed.problems, "");
  return parsed;
}

std::vector<Element> elements_named(const ParsedSvg& svg, const std::string& name) {
  std::vector<Element> out;
  for (const Element& e : svg.elements) {
    if (e.name == name) out.push_back(e);
  }
  return out;
}

std::vector<Shape> dots(const ParsedSvg& svg) {
  std::vector<Shape> out;
  for (const Shape& s : svg.shapes)
    if (s.dot) out.push_back(s);
  return out;
}

std::vector<Shape> segments(const ParsedSvg& svg) {
  std::vector<Shape> out;
  for (const Shape& s : svg.shapes)
    if (!s.dot) out.push_back(s);
  return out;
}

// The check the other tests rely on, on broken pictures it must catch.
TEST(SvgPicture, TheWellFormednessCheckCatchesBrokenSvg) {
  const auto svg = [](const std::string& body) {
    return R"(<svg width="10" height="10">)" + body + "</svg>\n";
  };
  const ParsedSvg good = parse_svg(svg(R"(<path d="M1 2h0M0 0L3 4L5 6"/>)"));
  EXPECT_EQ(good.problems, "");
  ASSERT_EQ(good.shapes.size(), 3u);
  EXPECT_TRUE(good.shapes[0].dot);
  EXPECT_EQ(good.shapes[2].x1, 3);
  EXPECT_EQ(good.shapes[2].y2, 6);
  for (const std::string& bad : {
           svg("<g>"),                                      // unclosed
           svg("a & b"),                                    // raw '&'
           svg(R"(<path d="Mnan 1h0"/>)"),                  // not finite
           svg(R"(<path d="M0 11L1 1"/>)"),                 // off the canvas
           svg(R"(<path d="M1 1L2"/>)"),                    // cut short
           svg(R"(<path d=""/>)"),                          // empty
           svg("") + "<svg></svg>\n",                       // two roots
       }) {
    EXPECT_NE(parse_svg(bad).problems, "") << bad;
  }
}

TEST(SvgPicture, DrawsZeroOneTwoAndCoincidentPoints) {
  const std::vector<std::vector<Point>> inputs = {
      {}, {Point(3, 4)}, {Point(0, 0), Point(1, 1)}, {Point(5, 5), Point(5, 5)}};
  for (const auto& points : inputs) {
    SvgPicture picture(points);
    picture.add_edges(std::vector<Edge>(points.size() > 1 ? 1 : 0, Edge{0, 1}));
    picture.add_points();
    const ParsedSvg svg = render(picture);
    EXPECT_EQ(dots(svg).size(), points.size());
    EXPECT_GT(svg.width, 0);
    EXPECT_GT(svg.height, 0);
  }
}

TEST(SvgPicture, CentresASinglePoint) {
  SvgPicture picture(std::vector<Point>{Point(1e9, -7)});
  picture.add_points();
  const ParsedSvg svg = render(picture);
  const Shape dot = dots(svg).at(0);
  EXPECT_DOUBLE_EQ(dot.x1, svg.width / 2);
  EXPECT_DOUBLE_EQ(dot.y1, svg.height / 2);
}

TEST(SvgPicture, FitsTheLongSideOfCollinearPointsTo800Pixels) {
  for (const bool horizontal : {true, false}) {
    std::vector<Point> points;
    for (const double t : {0.0, 0.25, 1.0})
      points.push_back(horizontal ? Point(t, 3) : Point(3, t));
    SvgPicture picture(points);
    picture.add_points();
    const auto d = dots(render(picture));
    const auto along = [&](std::size_t k) { return horizontal ? d[k].x1 : d[k].y1; };
    const auto across = [&](std::size_t k) { return horizontal ? d[k].y1 : d[k].x1; };
    EXPECT_DOUBLE_EQ(std::abs(along(2) - along(0)), 800);
    EXPECT_DOUBLE_EQ(std::abs(along(1) - along(0)), 200);
    EXPECT_EQ(across(0), across(2));
  }
}

TEST(SvgPicture, YAxisPointsUp) {
  SvgPicture picture(std::vector<Point>{Point(0, 0), Point(0, 1)});
  picture.add_points();
  const auto d = dots(render(picture));
  EXPECT_LT(d[1].y1, d[0].y1);
}

std::string svg_of_scaled_drawing(double scale) {
  const std::vector<Point> shape = {Point(0, 0), Point(3, 1), Point(2, 4), Point(-1, 2.5)};
  std::vector<Point> points;
  for (const Point& p : shape) points.emplace_back(p.x() * scale, p.y() * scale);
  SvgPicture picture(points);
  picture.add_edges(std::vector<Edge>{{0, 1}, {1, 2}, {2, 3}, {3, 0}},
                    {.colour = "grey", .width_px = 3, .dash_px = {4, 2}, .legend = "truth"});
  picture.add_points({.radius_px = 2, .legend = "samples"});
  std::ostringstream out;
  picture.write(out);
  return out.str();
}

TEST(SvgPicture, LooksTheSameWhateverTheScaleOfTheData) {
  // Powers of two scale exactly, so the pictures must be identical to the byte.
  EXPECT_EQ(svg_of_scaled_drawing(std::ldexp(1.0, -20)),
            svg_of_scaled_drawing(std::ldexp(1.0, 20)));
  const ParsedSvg small_svg = parse_svg(svg_of_scaled_drawing(1e-6));
  const ParsedSvg large_svg = parse_svg(svg_of_scaled_drawing(1e6));
  EXPECT_EQ(small_svg.problems + large_svg.problems, "");
  const auto& small = small_svg.elements;
  const auto& large = large_svg.elements;
  ASSERT_EQ(small.size(), large.size());
  for (std::size_t k = 0; k < small.size(); ++k) {
    ASSERT_EQ(small[k].name, large[k].name);
    if (small[k].attributes.count("stroke-width")) {
      EXPECT_EQ(small[k].attributes.at("stroke-width"), large[k].attributes.at("stroke-width"));
    }
  }
  ASSERT_EQ(small_svg.shapes.size(), large_svg.shapes.size());
  for (std::size_t k = 0; k < small_svg.shapes.size(); ++k) {
    const Shape &a = small_svg.shapes[k], &b = large_svg.shapes[k];
    EXPECT_EQ(a.dot, b.dot);
    for (const auto& [u, v] : {std::pair{a.x1, b.x1}, {a.y1, b.y1}, {a.x2, b.x2}, {a.y2, b.y2}}) EXPECT_NEAR(u, v, 0.011);
  }
}

TEST(SvgPicture, CopesWithExtremeCoordinates) {
  const double max = std::numeric_limits<double>::max();
  const double tiny = std::numeric_limits<double>::denorm_min();
  for (const auto& points : {std::vector<Point>{Point(-max, -max), Point(max, max), Point(0, 0)},
                             std::vector<Point>{Point(0, 0), Point(tiny, 2 * tiny)}}) {
    SvgPicture picture(points);
    picture.add_edges(std::vector<Edge>{{0, 1}});
    picture.add_points();
    EXPECT_EQ(dots(render(picture)).size(), points.size());
  }
}

TEST(SvgPicture, EscapesTitleLegendAndColours) {
  SvgPicture picture(std::vector<Point>{Point(0, 0), Point(1, 0)});
  picture.set_title("a<b & \"c\" 'd'\x01");
  picture.add_points({.colour = "\"><script>", .legend = "</text>"});
  std::ostringstream out;
  picture.write(out);
  const std::string svg = out.str();
  EXPECT_NE(svg.find(">a&lt;b &amp; &quot;c&quot; &apos;d&apos; </title>"), std::string::npos);
  EXPECT_EQ(svg.find("<script"), std::string::npos);
  render(picture);  // well-formed
}

TEST(SvgPicture, DrawsLayersInOrderWithTheirStyles) {
  const std::vector<Point> truth = {Point(0, 0), Point(1, 0), Point(1, 1)};
  const std::vector<Point> moved = {Point(0, 0.1), Point(1, 0.1), Point(2, 2)};
  SvgPicture picture(truth);
  picture.set_title("layers");
  picture.add_edges(std::vector<Edge>{{0, 1}, {1, 2}},
                    {.colour = "#bbbbbb", .width_px = 4, .opacity = 0.5, .legend = "truth"});
  picture.add_edges(moved, std::vector<Edge>{{1, 2}}, {.colour = "red", .dash_px = {4, 2}});
  picture.add_points();
  const ParsedSvg svg = render(picture);
  std::vector<Element> groups = elements_named(svg, "g");
  ASSERT_GE(groups.size(), 3u);
  EXPECT_EQ(groups[0].attributes["stroke"], "#bbbbbb");
  EXPECT_EQ(groups[0].attributes["stroke-width"], "4");
  EXPECT_EQ(groups[0].attributes["stroke-opacity"], "0.5");
  EXPECT_EQ(groups[1].attributes["stroke"], "red");
  EXPECT_EQ(groups[1].attributes["stroke-dasharray"], "4 2");
  EXPECT_EQ(groups[2].attributes["stroke"], "#000000");
  EXPECT_EQ(groups[2].attributes["stroke-width"], "5");  // a dot of radius 2.5
  const auto lines = segments(svg);
  EXPECT_EQ(lines.size(), 3u + 1u);  // + the legend swatch
  // The frame fits the moved point (2, 2) too: it lies on the right edge of the plot.
  EXPECT_DOUBLE_EQ(lines[2].x2, svg.width - 20);
}

TEST(SvgPicture, RejectsBadEdgesPointsAndStyles) {
  SvgPicture picture(std::vector<Point>{Point(0, 0), Point(1, 0)});
  EXPECT_THROW(picture.add_edges(std::vector<Edge>{{0, 2}}), std::out_of_range);
  EXPECT_THROW(picture.add_edges(std::vector<Edge>{}, {.opacity = 2}), std::invalid_argument);
  EXPECT_THROW(picture.add_edges(std::vector<Edge>{}, {.dash_px = {-1}}), std::invalid_argument);
  EXPECT_THROW(picture.add_points({.radius_px = std::nan("")}), std::invalid_argument);
  const std::vector<Point> bad = {Point(std::numeric_limits<double>::infinity(), 0)};
  EXPECT_THROW(SvgPicture{bad}, std::invalid_argument);
  EXPECT_THROW(picture.add_points(bad, {}), std::invalid_argument);
}

TEST(SvgPicture, WritesTheSameToAFileAsToAStream) {
  SvgPicture picture(std::vector<Point>{Point(0, 0), Point(1, 2)});
  picture.add_points();
  const testing::TemporaryDirectory dir;
  picture.write(dir.path() / "picture.svg");
  std::ostringstream out;
  picture.write(out);
  EXPECT_EQ(testing::read_bytes(dir.path() / "picture.svg"), out.str());
}

RC_GTEST_PROP(SvgPicture, AnyFinitePointsGiveAWellFormedPicture, ()) {
  const auto points = *rc::gen::container<std::vector<Point>>(
      rc::gen::construct<Point>(testing::finite_double(), testing::finite_double()));
  SvgPicture picture(points);
  std::vector<Edge> chain;
  for (std::size_t i = 1; i < points.size(); ++i) chain.emplace_back(i - 1, i);
  picture.add_edges(chain);
  picture.add_points();
  std::ostringstream out;
  picture.write(out);
  const ParsedSvg svg = parse_svg(out.str());
  RC_ASSERT(svg.problems == "");
  RC_ASSERT(dots(svg).size() == points.size());
  RC_ASSERT(segments(svg).size() == chain.size());  // chained or not, one segment per edge
}

}  // namespace
}  // namespace curvebench::geometry
