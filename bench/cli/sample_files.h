// A Sample on disk, as `curvebench sample`, `noise` and `outliers` write it: BASE.xy
// (points), BASE.edges (ground truth, `i j`), BASE.lfs (lfs per point, `nan` for an
// outlier), BASE.labels (`curve` or `outlier` per point) and, on request, BASE.svg.
#pragma once

#include <filesystem>

#include "geometry/lfs/local_feature_size.h"
#include "geometry/sampling/sample.h"

namespace curvebench::cli {

void write_sample(const std::filesystem::path& base, const geometry::Sample& sample);

// The curve (dense polyline), its estimated medial axis and the samples, outliers in red.
void write_sample_picture(const std::filesystem::path& file, const geometry::Local_feature_size& lfs,
                          const geometry::Sample& sample);

// A point file as a Sample of the curve (bench/runner/sampling_report.h's located_sample),
// edges from `edges` (may be empty).
geometry::Sample read_sample(const geometry::Local_feature_size& lfs, const std::filesystem::path& points,
                             const std::filesystem::path& edges);

}  // namespace curvebench::cli
