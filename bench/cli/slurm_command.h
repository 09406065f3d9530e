// `curvebench slurm (run SUITE ... | certify ... | rate ...) -o DIR --tasks N`: a sweep as
// a Slurm job array. It writes two batch scripts a person can read and adapt to a site:
//   DIR/slurm/array.sbatch  task K of N runs the command's shard K/N into DIR/shard-K,
//                           always with --resume, so a requeued or resubmitted task
//                           continues where it stopped;
//   DIR/slurm/merge.sbatch  `curvebench merge` of the N shards into DIR, then the report
//                           (run), the certification summary (certify) or the table (rate),
//                           submitted with --dependency=afterok on the array.
// With --submit it submits both with sbatch and prints their job ids.
#pragma once

#include <CLI/CLI.hpp>

namespace curvebench::cli {

void add_slurm_command(CLI::App& app);

}  // namespace curvebench::cli
