// SVG pictures of point sets and curves, for a person to look at: layers of edges and
// points drawn in the order they are added (add a ground truth first to see a
// reconstruction on top of it), each with its own style and optional legend entry.
//
// The picture fits everything drawn into 800 px on its long side (plus a margin), with
// the y axis pointing up. Stroke widths, dashes and point radii are in screen pixels, so a
// curve of size 1e-6 and the same curve of size 1e6 give the same picture. A single
// point, coincident points and collinear points (zero width or height) are centred.
//
//   SvgPicture picture(points);
//   picture.set_title("NN-crust on bunny.txt");
//   picture.add_edges(truth_edges, {.colour = "#bbbbbb", .width_px = 4, .legend = "ground truth"});
//   picture.add_edges(wrong_edges, {.colour = "red", .width_px = 2, .legend = "wrong"});
//   picture.add_points();
//   picture.write("bunny.svg");
#pragma once

#include <filesystem>
#include <iosfwd>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "geometry/edge.h"
#include "geometry/kernel.h"

namespace curvebench::geometry {

struct EdgeStyle {
  std::string colour = "#1f4e99";  // any SVG colour: "red", "#ff0000", "rgb(255,0,0)"
  double width_px = 1.5;
  double opacity = 1.0;  // 0 (invisible) to 1 (opaque)
  // The "= {}" initializers let callers write {.colour = "red"} under -Wextra.
  std::vector<double> dash_px = {};  // alternating dash and gap lengths; empty: solid
  std::string legend = {};           // label in the legend; empty: not listed
};

struct PointStyle {
  std::string colour = "#000000";
  double radius_px = 2.5;
  double opacity = 1.0;
  std::string legend = {};
};

class SvgPicture {
 public:
  // `points` are the ones that add_edges(edges, style) and add_points(style) draw.
  explicit SvgPicture(std::span<const Point> points = {});

  void set_title(std::string title);

  // Each throws std::out_of_range for an edge index not below points.size() and
  // std::invalid_argument for a non-finite coordinate or a negative, non-finite or
  // (for opacity) above-1 style number.
  void add_edges(std::span<const Edge> edges, const EdgeStyle& style = {});
  void add_edges(std::span<const Point> points, std::span<const Edge> edges,
                 const EdgeStyle& style);
  void add_points(const PointStyle& style = {});
  void add_points(std::span<const Point> points, const PointStyle& style);

  void write(std::ostream& out) const;
  // Throws std::filesystem::filesystem_error if the file cannot be written.
  void write(const std::filesystem::path& path) const;

 private:
  // What one layer draws (segments or points), and how.
  template <class Shape, class Style>
  struct Layer {
    std::vector<Shape> shapes;
    Style style;
  };
  using EdgeLayer = Layer<Kernel::Segment_2, EdgeStyle>;
  using PointLayer = Layer<Point, PointStyle>;

  std::vector<Point> points_;
  std::string title_;
  std::vector<std::variant<EdgeLayer, PointLayer>> layers_;
};

}  // namespace curvebench::geometry
