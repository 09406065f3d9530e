#include "bench/cli/image_command.h"

#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "bench/cli/sample_files.h"
#include "geometry/image/binary_image.h"
#include "geometry/curves/curve_spec.h"
#include "geometry/image/image_sampling.h"
#include "geometry/io/svg_picture.h"

namespace curvebench::cli {
namespace {

struct Rasterize_options {
  std::string curve;
  std::size_t resolution = 0;
  std::filesystem::path output;
};

struct Image_sample_options {
  std::filesystem::path input;
  std::string curve;
  std::size_t resolution = 0;
  double radius = 0;
  std::uint64_t seed = 0;
  std::filesystem::path base;
  bool svg = false;
};

const char* const curve_help =
    "Curve spec of closed curves: circle:r=1, ellipse:a=2,b=1, superellipse:a=1,b=1,n=4, fourier:seed=7, "
    "corner:angle=30, svg:FILE[,corner=DEG], glyph:[FONT:]CHAR, truth:POINTS:EDGES";
const char* const resolution_help = "Pixels on the longer side of the curve's bounding box plus a 2-pixel margin (8 to 16384)";

// Boundary pixels in light grey, the ground truth and the samples, in the samples' coordinates.
void write_picture(const std::filesystem::path& file, const std::string& title, const geometry::Binary_image& image,
                   const geometry::Image_sample& result, const geometry::Raster_frame* frame) {
  std::vector<geometry::Point> boundary;
  for (const auto& [x, y] : geometry::boundary_pixels(image)) {
    const double u = x + 0.5, v = y + 0.5;
    boundary.push_back(frame ? frame->to_curve(u, v) : geometry::Point(u, static_cast<double>(image.height) - v));
  }
  geometry::SvgPicture picture(result.sample.points);
  picture.set_title(title);
  picture.add_points(boundary, {.colour = "#c8c8c8", .radius_px = 0.8, .legend = "boundary pixels"});
  picture.add_edges(result.sample.edges, {.colour = "#1f4e99", .width_px = 1, .legend = "ground truth"});
  picture.add_points({.colour = "#000000", .radius_px = 2, .legend = "samples"});
  picture.write(file);
}

void run_image_sample(const Image_sample_options& o) {
  geometry::Binary_image image;
  std::optional<geometry::Raster_frame> frame;
  std::string source;
  if (!o.input.empty()) {
    image = geometry::read_netpbm(o.input);
    source = o.input.filename().string();
  } else {
    const geometry::Curve curve = geometry::make_curve(o.curve);
    frame.emplace();
    image = geometry::rasterize(curve, o.resolution, &*frame);
    source = curve.name + " at " + std::to_string(image.width) + " x " + std::to_string(image.height) + " pixels";
  }
  const geometry::Image_sample result =
      geometry::sample_image_boundary(image, o.radius, o.seed, frame ? &*frame : nullptr);
  write_sample(o.base, result.sample);
  if (o.svg) {
    std::ostringstream title;
    title << source << ": " << result.sample.size() << " samples, radius " << o.radius << " px";
    write_picture(std::filesystem::path(o.base) += ".svg", title.str(), image, result, frame ? &*frame : nullptr);
  }
  std::cout << o.base.string() << ".xy: " << result.sample.size() << " points, " << result.sample.edges.size()
            << " edges on " << result.loop_sizes.size() << " boundary loops\n";
}

}  // namespace

void add_rasterize_command(CLI::App& app) {
  auto o = std::make_shared<Rasterize_options>();
  CLI::App* command = app.add_subcommand("rasterize", "Fill a closed curve's interior into a binary PGM image (white object)");
  command->add_option("--curve", o->curve, curve_help)->required();
  command->add_option("--resolution", o->resolution, resolution_help)->required();
  command->add_option("-o,--output", o->output, "PGM image to write (P5, object 255, background 0)")->required();
  command->callback([o] {
    const geometry::Binary_image image = geometry::rasterize(geometry::make_curve(o->curve), o->resolution);
    geometry::write_pgm(image, o->output);
    std::cout << o->output.string() << ": " << image.width << " x " << image.height << " pixels, "
              << std::count(image.pixels.begin(), image.pixels.end(), 1) << " object pixels\n";
  });
}

void add_image_sample_command(CLI::App& app) {
  auto o = std::make_shared<Image_sample_options>();
  CLI::App* command = app.add_subcommand(
      "image-sample", "Sample the object boundary of a binary image by the survey's erasure method, with ground truth");
  auto* source = command->add_option_group("source", "exactly one image source");
  source->add_option("-i,--input", o->input, "Netpbm image (PBM or PGM; white object on black)")->check(CLI::ExistingFile);
  CLI::Option* curve = source->add_option("--curve", o->curve, std::string(curve_help) + " (rasterized first)");
  source->require_option(1);
  CLI::Option* resolution = command->add_option("--resolution", o->resolution, std::string(resolution_help) + " (with --curve)");
  curve->needs(resolution);
  resolution->needs(curve);
  command->add_option("--radius", o->radius, "erase the boundary pixels closer than R pixels to each sample")->required();
  command->add_option("--seed", o->seed, "seed of the random order of the pixels")->capture_default_str();
  command->add_option("-o,--output", o->base,
                      "write BASE.xy (pixel centres, y up; curve coordinates with --curve), BASE.edges, BASE.lfs (nan), "
                      "BASE.labels")
      ->required();
  command->add_flag("--svg", o->svg, "also draw boundary pixels, ground truth and samples to BASE.svg");
  command->callback([o] { run_image_sample(*o); });
}

}  // namespace curvebench::cli
