#include "geometry/curves/svg_path.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

#include "geometry/curves/curve_name.h"
#include "geometry/io/parse_error.h"
#include "geometry/curves/path_builder.h"
#include "geometry/io/text_file.h"

namespace curvebench::geometry {
namespace {

// Coordinates are 0 or of a magnitude in [1e-50, 1e50]: CGAL's point-to-segment distance
// (used by polylines) multiplies squared lengths, and fourth powers of coordinate
// differences must neither overflow nor underflow to subnormals.
constexpr double min_coordinate = 1e-50, max_coordinate = 1e50;

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool is_white(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }
char upper(char c) { return c >= 'a' && c <= 'z' ? char(c - 'a' + 'A') : c; }

// The numbers, letters and separators (white space, commas) of path data and transform lists.
class Scanner {
 public:
  explicit Scanner(std::string_view text) : text_(text) {}

  std::size_t position() const { return position_; }
  // Skips separators; whether anything follows.
  bool more() {
    while (position_ < text_.size() && (is_white(text_[position_]) || text_[position_] == ',')) ++position_;
    return position_ < text_.size();
  }
  char peek() const { return text_[position_]; }  // only after more() returned true
  void advance() { ++position_; }
  bool at_number() { return more() && (is_digit(peek()) || peek() == '.' || peek() == '-' || peek() == '+'); }
  std::string_view letters() {
    const std::size_t start = position_;
    while (position_ < text_.size() && is_letter(text_[position_])) ++position_;
    return text_.substr(start, position_ - start);
  }
  void expect(char c) {
    if (!more() || peek() != c) fail(position_, std::string("expected '") + c + "'");
    advance();
  }
  // sign? (digits (. digits?)? | . digits) ([eE] sign? digits)?: the longest such prefix, so
  // that "-.5.5" is -0.5 then 0.5 and "1e" is 1 then the letter e.
  double number() {
    if (!more()) fail(position_, "expected a number, found the end");
    const std::size_t start = position_;
    std::size_t i = start;
    const auto digits = [&] {
      const std::size_t from = i;
      while (i < text_.size() && is_digit(text_[i])) ++i;
      return i > from;
    };
    if (text_[i] == '+' || text_[i] == '-') ++i;
    bool mantissa = digits();
    if (i < text_.size() && text_[i] == '.') {
      ++i;
      mantissa = digits() || mantissa;
    }
    if (!mantissa) fail(start, "expected a number");
    if (i < text_.size() && (text_[i] == 'e' || text_[i] == 'E')) {
      std::size_t j = i + 1;
      if (j < text_.size() && (text_[j] == '+' || text_[j] == '-')) ++j;
      if (j < text_.size() && is_digit(text_[j])) {
        i = j;
        digits();
      }
    }
    double value = 0;
    const char* first = text_.data() + start + (text_[start] == '+' ? 1 : 0);  // from_chars takes no '+'
    const auto [end, error] = std::from_chars(first, text_.data() + i, value);
    if (error != std::errc() || end != text_.data() + i || !std::isfinite(value))
      fail(start, "number " + std::string(text_.substr(start, i - start)) + " outside the range of double");
    position_ = i;
    return value;
  }

  [[noreturn]] static void fail(std::size_t position, const std::string& message) {
    throw Svg_syntax_error(position, message);
  }

 private:
  std::string_view text_;
  std::size_t position_ = 0;
};

// Reads path data command by command. Points are kept in user space, where relative
// commands add to them, and go to the Path_builder transformed.
class Path_parser {
 public:
  Path_parser(std::string_view data, const Affine_transformation& transform, double corner_angle)
      : scanner_(data), transform_(transform), builder_(corner_angle) {}

  std::vector<Curve_component> parse() {
    char command = 0;
    while (scanner_.more()) {
      const std::size_t at = scanner_.position();
      const char letter = scanner_.peek();
      if (command == 0 && letter != 'M' && letter != 'm') Scanner::fail(at, "path data must begin with M or m");
      if (!is_letter(letter)) Scanner::fail(at, "expected a command letter");
      if (std::string_view("MLHVCSQTZ").find(upper(letter)) == std::string_view::npos)
        Scanner::fail(at, std::string("unsupported command '") + letter + "'");
      scanner_.advance();
      command = letter;
      if (upper(command) == 'Z') {
        builder_.close();
        current_ = start_;
        cubic_control_ = quadratic_control_ = std::nullopt;  // S and T after Z reflect nothing
        continue;
      }
      do {  // one set of parameters, then more while numbers follow; after M they are lines
        segment(command);
        if (upper(command) == 'M') command = command == 'M' ? 'L' : 'l';
      } while (scanner_.at_number());
    }
    return builder_.finish();
  }

 private:
  void segment(char command) {
    const bool relative = command >= 'a';
    const auto previous_cubic = std::exchange(cubic_control_, std::nullopt);
    const auto previous_quadratic = std::exchange(quadratic_control_, std::nullopt);
    const auto reflected = [&](const std::optional<Point>& control) {
      return control ? current_ + (current_ - *control) : current_;
    };
    const auto image = [&](const Point& p) { return transform_(p); };
    Point to;
    switch (upper(command)) {
      case 'M':
        start_ = current_ = read_point(relative);
        builder_.move_to(image(start_));
        return;
      case 'L':
        to = read_point(relative);
        builder_.line_to(image(to));
        break;
      case 'H':
        to = checked(Point(read_coordinate(relative ? current_.x() : 0), current_.y()));
        builder_.line_to(image(to));
        break;
      case 'V':
        to = checked(Point(current_.x(), read_coordinate(relative ? current_.y() : 0)));
        builder_.line_to(image(to));
        break;
      case 'C':
      case 'S': {
        const Point first = upper(command) == 'C' ? read_point(relative) : checked(reflected(previous_cubic));
        const Point second = read_point(relative);
        to = read_point(relative);
        builder_.cubic_to(image(first), image(second), image(to));
        cubic_control_ = second;
        break;
      }
      default: {  // Q, T
        const Point control = upper(command) == 'Q' ? read_point(relative) : checked(reflected(previous_quadratic));
        to = read_point(relative);
        builder_.quadratic_to(image(control), image(to));
        quadratic_control_ = control;
      }
    }
    current_ = to;
  }

  double read_coordinate(double offset) {
    scanner_.more();
    position_ = scanner_.position();
    return offset + scanner_.number();
  }
  Point read_point(bool relative) {
    const double x = read_coordinate(relative ? current_.x() : 0);
    const std::size_t at = position_;
    const double y = read_coordinate(relative ? current_.y() : 0);
    position_ = at;
    return checked(Point(x, y));
  }
  // p, after making sure that its coordinates and those of its image are in range.
  Point checked(const Point& p) const {
    const Point image = transform_(p);
    for (const double c : {p.x(), p.y(), image.x(), image.y()})
      if (c != 0 && !(std::abs(c) >= min_coordinate && std::abs(c) <= max_coordinate))
        Scanner::fail(position_, "coordinate " + format_number(c) +
                                     " (after relative offsets and transform) is neither 0 nor of a magnitude in [1e-50, 1e50]");
    return p;
  }

  Scanner scanner_;
  Affine_transformation transform_;
  std::size_t position_ = 0;  // where the coordinate being read starts, for messages
  Point start_ = CGAL::ORIGIN, current_ = CGAL::ORIGIN;
  std::optional<Point> cubic_control_, quadratic_control_;  // of the previous segment, for S and T
  Path_builder builder_;  // gets the transformed points
};

// What read_svg_curve needs of an XML tag.
struct Tag {
  std::string_view name;  // without a namespace prefix ("svg:path" -> "path")
  std::vector<std::pair<std::string_view, std::size_t>> attributes;  // name, offset of the value
  bool end = false;           // </name>
  bool self_closing = false;  // <name ... />
};

// Reads the tags of an SVG file one after another; errors name the file and line.
class Svg_tag_scanner {
 public:
  Svg_tag_scanner(std::string text, std::string file) : text_(std::move(text)), file_(std::move(file)) {}

  // The next start or end tag, skipping text, comments, processing instructions, CDATA
  // sections and declarations; nothing at the end of the file.
  std::optional<Tag> next() {
    static constexpr std::array<std::pair<std::string_view, std::string_view>, 4> skipped{
        {{"<!--", "-->"}, {"<?", "?>"}, {"<![CDATA[", "]]>"}, {"<!", ">"}}};
    while ((position_ = text_.find('<', position_)) != std::string::npos) {
      const auto skip = std::find_if(skipped.begin(), skipped.end(),
                                     [&](const auto& s) { return text_.compare(position_, s.first.size(), s.first) == 0; });
      if (skip == skipped.end()) return tag();
      const std::size_t end = text_.find(skip->second, position_ + skip->first.size());
      if (end == std::string::npos) fail(position_, std::string(skip->first).append(" is never closed"));
      position_ = end + skip->second.size();
    }
    return std::nullopt;
  }

  // The attribute value that starts at `offset` (just past its opening quote).
  std::string_view value(std::size_t offset) const {
    return std::string_view(text_).substr(offset, text_.find(text_[offset - 1], offset) - offset);
  }

  [[noreturn]] void fail(std::size_t offset, std::string_view message) const {
    throw ParseError(file_, 1 + std::count(text_.begin(), text_.begin() + std::ptrdiff_t(offset), '\n'), message);
  }

 private:
  Tag tag() {
    const std::size_t open = position_++;
    Tag tag;
    tag.end = position_ < text_.size() && text_[position_] == '/';
    position_ += tag.end;
    tag.name = name();
    if (const auto colon = tag.name.rfind(':'); colon != std::string_view::npos) tag.name.remove_prefix(colon + 1);
    if (tag.name.empty()) fail(open, "'<' not followed by a tag name");
    for (;;) {
      skip_white();
      if (position_ >= text_.size()) fail(open, "tag never closed by '>'");
      if (text_.compare(position_, 2, "/>") == 0 || text_[position_] == '>') {
        tag.self_closing = text_[position_] == '/';
        position_ = text_.find('>', position_) + 1;
        return tag;
      }
      const std::string_view attribute = name();
      skip_white();
      if (attribute.empty() || tag.end || position_ >= text_.size() || text_[position_] != '=')
        fail(position_, "expected an attribute name=\"value\"");
      ++position_;
      skip_white();
      const char quote = position_ < text_.size() ? text_[position_] : 0;
      const std::size_t close = quote == '"' || quote == '\'' ? text_.find(quote, position_ + 1) : std::string::npos;
      if (close == std::string::npos) fail(position_, "expected a quoted attribute value");
      tag.attributes.emplace_back(attribute, position_ + 1);
      position_ = close + 1;
    }
  }
  std::string_view name() {
    const std::size_t start = position_;
    position_ = std::min(text_.find_first_of(" \t\r\n/>=", start), text_.size());
    return std::string_view(text_).substr(start, position_ - start);
  }
  void skip_white() {
    while (position_ < text_.size() && is_white(text_[position_])) ++position_;
  }

  std::string text_, file_;
  std::size_t position_ = 0;
};

}  // namespace

Curve parse_svg_path(std::string_view data, const Affine_transformation& transform, double corner_angle) {
  return Curve{"svg-path", Path_parser(data, transform, corner_angle).parse()};
}

Affine_transformation parse_svg_transform(std::string_view list) {
  Scanner scanner(list);
  Affine_transformation result;
  while (scanner.more()) {
    const std::size_t at = scanner.position();
    const std::string_view name = scanner.letters();
    scanner.expect('(');
    std::vector<double> a;
    while (scanner.at_number()) a.push_back(scanner.number());
    scanner.expect(')');
    const auto arguments = [&](std::initializer_list<std::size_t> counts) {
      if (std::find(counts.begin(), counts.end(), a.size()) == counts.end())
        Scanner::fail(at, std::string(name) + " with " + std::to_string(a.size()) + " arguments");
    };
    const auto radians = [](double degrees) { return degrees * std::numbers::pi / 180; };
    if (name == "matrix") {
      arguments({6});
      result = result * Affine_transformation(a[0], a[2], a[4], a[1], a[3], a[5]);
    } else if (name == "translate") {
      arguments({1, 2});
      result = result * Affine_transformation(1, 0, a[0], 0, 1, a.size() == 2 ? a[1] : 0);
    } else if (name == "scale") {
      arguments({1, 2});
      result = result * Affine_transformation(a[0], 0, 0, 0, a.size() == 2 ? a[1] : a[0], 0);
    } else if (name == "rotate") {
      arguments({1, 3});
      const double c = std::cos(radians(a[0])), s = std::sin(radians(a[0]));
      const double x = a.size() == 3 ? a[1] : 0, y = a.size() == 3 ? a[2] : 0;
      // translate(x y) rotate(a) translate(-x -y)
      result = result * Affine_transformation(c, -s, x - c * x + s * y, s, c, y - s * x - c * y);
    } else if (name == "skewX") {
      arguments({1});
      result = result * Affine_transformation(1, std::tan(radians(a[0])), 0, 0, 1, 0);
    } else if (name == "skewY") {
      arguments({1});
      result = result * Affine_transformation(1, 0, 0, std::tan(radians(a[0])), 1, 0);
    } else {
      Scanner::fail(at, "unknown transform '" + std::string(name) + "'");
    }
  }
  return result;
}

Curve read_svg_curve(const std::filesystem::path& file, double corner_degrees) {
  if (!(corner_degrees >= 0 && corner_degrees <= 180))
    throw std::invalid_argument("svg: the corner angle must be in [0, 180] degrees");
  const double corner_angle = corner_degrees * std::numbers::pi / 180;
  Svg_tag_scanner scanner(read_text_file(file), file.string());
  Curve curve{"svg:" + file.string() + (corner_degrees == default_svg_corner_degrees ? "" : ",corner=" + format_number(corner_degrees)), {}};
  std::vector<Affine_transformation> open{Affine_transformation()};  // of each open element, the document's first
  while (const auto tag = scanner.next()) {
    if (tag->end) {
      if (open.size() > 1) open.pop_back();
      continue;
    }
    const auto attribute = [&](std::string_view name) -> std::optional<std::size_t> {
      for (const auto& [attribute_name, offset] : tag->attributes)
        if (attribute_name == name) return offset;
      return std::nullopt;
    };
    // parse(value of the attribute at `offset`), with a syntax error turned into a ParseError.
    const auto parsed = [&](std::string_view name, std::size_t offset, const auto& parse) {
      try {
        return parse(scanner.value(offset));
      } catch (const Svg_syntax_error& error) {
        scanner.fail(offset + error.position(), std::string(name) + " attribute: " + error.what());
      }
    };
    Affine_transformation transform = open.back();
    if (const auto offset = attribute("transform")) transform = transform * parsed("transform", *offset, parse_svg_transform);
    if (const auto offset = attribute("d"); offset && tag->name == "path") {
      auto path = parsed("d", *offset, [&](std::string_view data) { return parse_svg_path(data, transform, corner_angle); });
      std::move(path.components.begin(), path.components.end(), std::back_inserter(curve.components));
    }
    if (!tag->self_closing) open.push_back(transform);
  }
  return curve;
}

}  // namespace curvebench::geometry
