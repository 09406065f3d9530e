// The survey's discrete sampling tool (survey, "Sampling Tools": "It first extracts the
// pixels lying on the object boundary by comparing each pixel with its 8-neighborhood.
// Then ... randomly picks a pixel at position (x,y), inserts a point at the location
// (x,y), and erase all boundary pixels lying at a distance less than r from (x,y)"), plus
// a ground truth, which the survey's tool does not give: the samples in the order the
// object's boundary passes them.
//
// Everything here is integer arithmetic on pixel positions; the only real number, the
// radius, enters through one exactly computed integer threshold (erasure_threshold).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "geometry/image/binary_image.h"
#include "geometry/sampling/sample.h"

namespace curvebench::geometry {

using Pixel = std::pair<int, int>;  // (x, y): column, and row counted from the top

// Object pixels with at least one background pixel among their 8 neighbours (pixels
// outside the image count as background), in row-major order. Throws
// std::invalid_argument if pixels.size() != width * height or above max_image_pixels.
std::vector<Pixel> boundary_pixels(const Binary_image& image);

// The object's boundary as closed loops, each the cyclic sequence of boundary pixels it
// passes. A loop follows the crack boundary (the unit edges between 4-adjacent object and
// background pixels) with the object on its left as drawn (y down): counterclockwise around
// an object, clockwise around a hole. Where two object pixels touch only at a corner, the
// loop passes from one to the other (the object is 8-connected, as its boundary pixels
// are). Each crack edge contributes the object pixel beside it, each concave corner the
// object pixel at the corner (so that every boundary pixel lies on some loop, even one
// whose background neighbours are all diagonal); consecutive repeats are dropped (also
// across the loop's end), so consecutive pixels are distinct 8-neighbours. A pixel may lie
// on several loops, or twice on one (a line one pixel wide). Loops are found, listed and
// started at their first crack edge in the order of pixels (row-major) and of each pixel's
// sides (bottom, left, top, right).
std::vector<std::vector<Pixel>> boundary_contours(const Binary_image& image);

// The integer T with n < T <=> n < radius² for every integer n >= 0, so that the erasure
// "distance less than r" is the exact integer test dx² + dy² < T. Computed without
// rounding error: radius² = p + e exactly with p = radius * radius and
// e = fma(radius, radius, -p). Radii above 2^29 count as 2^29 (beyond every distance in
// an image of max_image_pixels). Throws std::invalid_argument unless radius > 0.
std::uint64_t erasure_threshold(double radius);

// What sample_image_boundary returns: the samples as a Sample with its ground truth, and
// where they came from in the image.
struct Image_sample {
  // Points at the centres of the sampled pixels: (x + 0.5, height - y - 0.5), i.e. image
  // coordinates with the y axis pointing up so the samples look like the image, or mapped
  // by a Raster_frame to curve coordinates. lfs NaN, locations unknown (Curve_location{}),
  // every label curve_point. Ground truth: for each boundary loop in turn, the samples not
  // on an earlier loop, in the order the loop first passes them, joined as a cycle
  // (3 or more samples), one edge (2) or none (1). Points come in that order, as in every
  // Sample: edges i -> i + 1 along a loop, and the closing edge of its cycle.
  Sample sample;
  std::vector<Pixel> pixels;  // the pixel of each point
  std::vector<std::size_t> loop_sizes;  // samples per loop that received any, in order
};

// The survey's erasure: boundary pixels in a random order (a Fisher-Yates shuffle driven
// by Seeded_random, so the same seed gives the same bytes everywhere); each one not yet
// erased becomes a sample and erases every boundary pixel q with
// (q.x - p.x)² + (q.y - p.y)² < radius² (itself included). So the samples are pairwise at
// least `radius` apart and every boundary pixel is closer than `radius` to one. The disc
// is walked row by row in the row-major list of boundary pixels (binary search per row),
// so a sample costs O(min(radius, height) log n) plus the boundary pixels in its disc (a
// pixel lies in the discs of at most a few samples, as they are pairwise >= radius apart),
// with no memory beyond the list. `frame`, if given, maps the points to
// curve coordinates. Throws std::invalid_argument unless radius > 0, or for an
// inconsistent image (as boundary_pixels).
Image_sample sample_image_boundary(const Binary_image& image, double radius, std::uint64_t seed,
                                   const Raster_frame* frame = nullptr);

}  // namespace curvebench::geometry
