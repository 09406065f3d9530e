// The shard of a Slurm array task: `sbatch --array=A-B` starts B - A + 1 tasks of one
// script, each with SLURM_ARRAY_TASK_ID (A..B), SLURM_ARRAY_TASK_MIN (A), _MAX (B) and
// _COUNT set, so `curvebench run`, `certify` and `rate` without --shard run shard
// ID - MIN + 1 of MAX - MIN + 1 (run.h says which jobs shard K of N holds).
// An array that is not one range (`--array=1,5,9`, `--array=1-9:2`) cannot be read as
// shards: its COUNT is not MAX - MIN + 1, and it is refused rather than guessed at.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>

namespace curvebench::bench {

// The environment variables as given (unset: nullopt).
struct Slurm_array_task {
  // SLURM_ARRAY_TASK_ID.
  std::optional<std::string> id = std::nullopt, min = std::nullopt, max = std::nullopt, count = std::nullopt;
  // \var min
  // SLURM_ARRAY_TASK_MIN.
  // \var max
  // SLURM_ARRAY_TASK_MAX.
  // \var count
  // SLURM_ARRAY_TASK_COUNT.
};

// Reads SLURM_ARRAY_TASK_ID, _MIN, _MAX and _COUNT from this process's environment.
Slurm_array_task slurm_array_task_from_environment();

// (K, N) of the task, or nullopt outside an array (no SLURM_ARRAY_TASK_ID). Throws
// std::invalid_argument naming the variable when the values are not numbers, MIN or both
// MAX and COUNT are missing, the ID lies outside MIN..MAX, or COUNT contradicts MIN..MAX.
std::optional<std::pair<std::size_t, std::size_t>> shard_of_array_task(const Slurm_array_task& task);

// The shard a command runs: --shard K/N when given (`option` not empty), else the array
// task's, else the whole run (1/1).
std::pair<std::size_t, std::size_t> chosen_shard(const std::string& option, const Slurm_array_task& task);

}  // namespace curvebench::bench
