// `curvebench tightness -a ALG [-a ALG ...] [--rho] [--seconds N] [--seed S] [-o DIR] [--json]`:
// the tightness search (certify/tightness_search.h) for each algorithm's proven bound: the
// failing case of smallest measured epsilon (rho) found, written to DIR/ALG (points.xy,
// truth.edges, reconstruction.edges, picture.svg, curve.txt, case.json, replay.sh), and the
// table of proven bound b, smallest failure f and f / b.
#pragma once

#include <CLI/CLI.hpp>

namespace curvebench::cli {

void add_tightness_command(CLI::App& app);

}  // namespace curvebench::cli
