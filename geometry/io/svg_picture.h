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

// How a layer of edges is drawn. Lengths are in screen pixels, whatever the data's units.
struct EdgeStyle {
  std::string colour = "#1f4e99";  // any SVG colour: "red", "#ff0000", "rgb(255,0,0)"
  double width_px = 1.5;  // stroke width, >= 0
  double opacity = 1.0;  // 0 (invisible) to 1 (opaque)
  // The "= {}" initializers let callers write {.colour = "red"} under -Wextra.
  std::vector<double> dash_px = {};  // alternating dash and gap lengths; empty: solid
  std::string legend = {};           // label in the legend; empty: not listed
};

// How a layer of points is drawn: round dots, their radius in screen pixels.
struct PointStyle {
  std::string colour = "#000000";  // any SVG colour, as in EdgeStyle
  double radius_px = 2.5;          // dot radius, >= 0
  double opacity = 1.0;            // 0 (invisible) to 1 (opaque)
  std::string legend = {};         // label in the legend; empty: not listed
};

// A picture built layer by layer, then written as an SVG document (see above). Keeps
// copies of every point given, so the spans passed in need not outlive the call.
class SvgPicture {
 public:
  // `points` are the ones that add_edges(edges, style) and add_points(style) draw.
  // They are fitted into the picture even if no layer draws them. Throws
  // std::invalid_argument for a non-finite coordinate.
  explicit SvgPicture(std::span<const Point> points = {});

  // A title, centred above the drawing and written as the document's `<title>`; empty
  // (the default): none.
  void set_title(std::string title);

  // A layer of segments, `edges` indexing the picture's points or the given `points`.
  // Each throws std::out_of_range for an edge index not below points.size() and
  // std::invalid_argument for a non-finite coordinate or a negative, non-finite or
  // (for opacity) above-1 style number.
  void add_edges(std::span<const Edge> edges, const EdgeStyle& style = {});
  // The same with `edges` indexing `points`, which need not be the picture's.
  void add_edges(std::span<const Point> points, std::span<const Edge> edges,
                 const EdgeStyle& style);
  // A layer of the picture's points.
  void add_points(const PointStyle& style = {});
  // A layer of other points. Like every layer, they widen the picture to fit them.
  void add_points(std::span<const Point> points, const PointStyle& style);

  // The SVG document, fitted to the picture's points and every layer.
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
