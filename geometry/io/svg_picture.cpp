#include "geometry/io/svg_picture.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <numeric>
#include <ostream>
#include <stdexcept>
#include <string_view>

#include "geometry/io/text_file.h"

namespace curvebench::geometry {
namespace {

constexpr double kPlotSize = 800;  // long side of the area the data is fitted into
constexpr double kMargin = 20;     // around that area, so points and strokes are not cut
constexpr double kMinSide = 160;   // of the canvas, for a single point or a straight line
constexpr double kTitleBand = 32;
constexpr double kLegendRow = 20;

// Canvas pixel coordinates of data points: the centre of the data's bounding box goes to
// the centre of the plot area, its larger half-extent to kPlotSize / 2, y up.
class Viewport {
 public:
  Viewport(const CGAL::Bbox_2& box, double top_band, double bottom_band) {
    if (box.xmin() <= box.xmax()) {
      // std::midpoint and distances to it, rather than xmax - xmin, which can overflow.
      centre_x_ = std::midpoint(box.xmin(), box.xmax());
      centre_y_ = std::midpoint(box.ymin(), box.ymax());
      half_width_ = std::max(box.xmax() - centre_x_, centre_x_ - box.xmin());
      half_height_ = std::max(box.ymax() - centre_y_, centre_y_ - box.ymin());
      half_extent_ = std::max(half_width_, half_height_);
    }
    width_ = std::max(kMinSide, 2 * (kMargin + pixels(half_width_)));
    const double plot_height = std::max(kMinSide, 2 * (kMargin + pixels(half_height_)));
    height_ = top_band + plot_height + bottom_band;
    centre_x_px_ = width_ / 2;
    centre_y_px_ = top_band + plot_height / 2;
  }

  double x(double data_x) const { return centre_x_px_ + pixels(data_x - centre_x_); }
  double y(double data_y) const { return centre_y_px_ - pixels(data_y - centre_y_); }
  double width() const { return width_; }
  double height() const { return height_; }

 private:
  // Divides before scaling: the ratio is at most 1 even for subnormal or huge extents.
  double pixels(double data_length) const {
    return half_extent_ > 0 ? data_length / half_extent_ * (kPlotSize / 2) : 0;
  }

  double centre_x_ = 0, centre_y_ = 0;
  double half_width_ = 0, half_height_ = 0, half_extent_ = 0;
  double width_ = 0, height_ = 0, centre_x_px_ = 0, centre_y_px_ = 0;
};

// Pixel values rounded to 1/100 px (finer is invisible and bloats files), shortest form.
std::string number(double value) {
  std::array<char, 32> text;
  // Values beyond 1e15 px (absurd, but finite styles allow them) have no fraction to drop,
  // and value * 100 could overflow. + 0.0 turns -0 into 0.
  const double rounded = (std::abs(value) < 1e15 ? std::round(value * 100) / 100 : value) + 0.0;
  return std::string(text.data(), std::to_chars(text.begin(), text.end(), rounded).ptr);
}

// For text and attribute values. Control characters are not allowed in XML 1.0 at all,
// not even escaped, so they become spaces.
std::string xml_escaped(std::string_view text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
    }
  }
  return out;
}

void require(bool condition, const char* message) {
  if (!condition) throw std::invalid_argument(std::string("SvgPicture: ") + message);
}

bool is_length(double px) { return std::isfinite(px) && px >= 0; }
bool is_opacity(double opacity) { return opacity >= 0 && opacity <= 1; }

void require_finite(std::span<const Point> points) {
  require(std::ranges::all_of(
              points, [](const Point& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }),
          "a point has a non-finite coordinate");
}

// The presentation attributes of a layer, shared by its group and its legend swatch.
std::string attributes(const EdgeStyle& style) {
  std::string out = "fill=\"none\" stroke=\"" + xml_escaped(style.colour) + "\" stroke-width=\"" +
                    number(style.width_px) + "\" stroke-opacity=\"" + number(style.opacity) +
                    "\" stroke-linecap=\"round\"";
  if (!style.dash_px.empty()) {
    out += " stroke-dasharray=\"";
    for (std::size_t k = 0; k < style.dash_px.size(); ++k) {
      if (k > 0) out += ' ';
      out += number(style.dash_px[k]);
    }
    out += '"';
  }
  return out;
}

// Points are dots: zero-length strokes with round caps, as wide as the dot. One path per
// layer ("M x yL x y" per segment, "M x yh0" per dot) is a third the size of an element
// per shape (a chain of segments shares its vertices), which matters for a benchmark
// run's thousands of pictures.
std::string attributes(const PointStyle& style) {
  return "fill=\"none\" stroke=\"" + xml_escaped(style.colour) + "\" stroke-width=\"" + number(2 * style.radius_px) +
         "\" stroke-opacity=\"" + number(style.opacity) + "\" stroke-linecap=\"round\"";
}

void write_segment(std::ostream& out, double x1, double y1, double x2, double y2) {
  out << 'M' << number(x1) << ' ' << number(y1) << 'L' << number(x2) << ' ' << number(y2);
}

// Segments as path data; a segment that starts (or ends) where the last one ended
// continues it ("L x y"), so that a chain costs one vertex per segment.
void write_segments(std::ostream& out, const Viewport& view, std::span<const Kernel::Segment_2> segments) {
  std::string last;
  for (const auto& s : segments) {
    const std::string a = number(view.x(s.source().x())) + ' ' + number(view.y(s.source().y()));
    const std::string b = number(view.x(s.target().x())) + ' ' + number(view.y(s.target().y()));
    if (a == last) {
      out << 'L' << b, last = b;
    } else if (b == last) {
      out << 'L' << a, last = a;
    } else {
      out << 'M' << a << 'L' << b, last = b;
    }
  }
}

void write_dot(std::ostream& out, double x, double y) { out << 'M' << number(x) << ' ' << number(y) << "h0"; }

void write_layer(std::ostream& out, const Viewport& view,
                 std::span<const Kernel::Segment_2> segments, const EdgeStyle& style) {
  out << "<g " << attributes(style) << ">";
  if (!segments.empty()) {
    out << "<path d=\"";
    write_segments(out, view, segments);
    out << "\"/>";
  }
  out << "</g>\n";
}

void write_layer(std::ostream& out, const Viewport& view, std::span<const Point> points,
                 const PointStyle& style) {
  out << "<g " << attributes(style) << ">";
  if (!points.empty()) {
    out << "<path d=\"";
    for (const Point& p : points) write_dot(out, view.x(p.x()), view.y(p.y()));
    out << "\"/>";
  }
  out << "</g>\n";
}

// A legend row: a short sample of the layer's style, then its label.
void write_swatch(std::ostream& out, double x, double y, const EdgeStyle& style) {
  out << "<g " << attributes(style) << "><path d=\"";
  write_segment(out, x, y, x + 24, y);
  out << "\"/></g>\n";
}

void write_swatch(std::ostream& out, double x, double y, const PointStyle& style) {
  out << "<g " << attributes(style) << "><path d=\"";
  write_dot(out, x + 12, y);
  out << "\"/></g>\n";
}

}  // namespace

SvgPicture::SvgPicture(std::span<const Point> points) : points_(points.begin(), points.end()) {
  require_finite(points_);
}

void SvgPicture::set_title(std::string title) { title_ = std::move(title); }

void SvgPicture::add_edges(std::span<const Edge> edges, const EdgeStyle& style) {
  add_edges(points_, edges, style);
}

void SvgPicture::add_edges(std::span<const Point> points, std::span<const Edge> edges,
                           const EdgeStyle& style) {
  require_finite(points);
  require(is_length(style.width_px), "width_px must be finite and >= 0");
  require(is_opacity(style.opacity), "opacity must be in [0, 1]");
  require(std::ranges::all_of(style.dash_px, is_length), "dash_px must be finite and >= 0");
  EdgeLayer layer{.shapes = {}, .style = style};
  layer.shapes.reserve(edges.size());
  for (const auto& [i, j] : edges) {
    if (i >= points.size() || j >= points.size()) {
      throw std::out_of_range("SvgPicture::add_edges: edge (" + std::to_string(i) + ", " +
                              std::to_string(j) + ") on " + std::to_string(points.size()) +
                              " points");
    }
    layer.shapes.emplace_back(points[i], points[j]);
  }
  layers_.emplace_back(std::move(layer));
}

void SvgPicture::add_points(const PointStyle& style) { add_points(points_, style); }

void SvgPicture::add_points(std::span<const Point> points, const PointStyle& style) {
  require_finite(points);
  require(is_length(style.radius_px), "radius_px must be finite and >= 0");
  require(is_opacity(style.opacity), "opacity must be in [0, 1]");
  layers_.emplace_back(PointLayer{.shapes = {points.begin(), points.end()}, .style = style});
}

void SvgPicture::write(std::ostream& out) const {
  CGAL::Bbox_2 box = CGAL::bbox_2(points_.begin(), points_.end());
  std::size_t legend_rows = 0;
  for (const auto& layer : layers_) {
    std::visit(
        [&](const auto& l) {
          for (const auto& shape : l.shapes) box += shape.bbox();
          legend_rows += !l.style.legend.empty();
        },
        layer);
  }
  const double top_band = title_.empty() ? 0 : kTitleBand;
  const double legend_band =
      legend_rows ? kLegendRow * static_cast<double>(legend_rows) + kMargin / 2 : 0;
  const Viewport view(box, top_band, legend_band);

  const std::string width = number(view.width());
  const std::string height = number(view.height());
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << " " << height << "\">\n";
  if (!title_.empty()) out << "<title>" << xml_escaped(title_) << "</title>\n";
  out << "<rect width=\"" << width << "\" height=\"" << height << "\" fill=\"white\"/>\n";
  if (!title_.empty()) {
    out << "<text x=\"" << number(view.width() / 2)
        << "\" y=\"22\" text-anchor=\"middle\" font-family=\"sans-serif\" font-size=\"16\">"
        << xml_escaped(title_) << "</text>\n";
  }
  for (const auto& layer : layers_) {
    std::visit([&](const auto& l) { write_layer(out, view, l.shapes, l.style); }, layer);
  }
  double row_y = view.height() - legend_band + kLegendRow / 2;
  for (const auto& layer : layers_) {
    std::visit(
        [&](const auto& l) {
          if (l.style.legend.empty()) return;
          write_swatch(out, kMargin, row_y, l.style);
          out << "<text x=\"" << number(kMargin + 32) << "\" y=\"" << number(row_y + 4)
              << "\" font-family=\"sans-serif\" font-size=\"12\">" << xml_escaped(l.style.legend)
              << "</text>\n";
          row_y += kLegendRow;
        },
        layer);
  }
  out << "</svg>\n";
}

void SvgPicture::write(const std::filesystem::path& path) const {
  write_text_file(path, [this](std::ostream& out) { write(out); });
}

}  // namespace curvebench::geometry
