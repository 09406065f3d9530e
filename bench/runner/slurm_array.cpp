#include "bench/runner/slurm_array.h"

#include <charconv>
#include <cstdlib>
#include <stdexcept>

#include "bench/runner/run.h"

namespace curvebench::bench {
namespace {

std::optional<std::string> environment_variable(const char* name) {
  const char* value = std::getenv(name);
  return value ? std::optional<std::string>(value) : std::nullopt;
}

// A whole non-negative decimal number, or a message naming the variable.
std::size_t number_of(const std::string& text, const char* variable) {
  std::size_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size())
    throw std::invalid_argument(std::string(variable) + "='" + text + "' is not a task number");
  return value;
}

}  // namespace

Slurm_array_task slurm_array_task_from_environment() {
  return {.id = environment_variable("SLURM_ARRAY_TASK_ID"),
          .min = environment_variable("SLURM_ARRAY_TASK_MIN"),
          .max = environment_variable("SLURM_ARRAY_TASK_MAX"),
          .count = environment_variable("SLURM_ARRAY_TASK_COUNT")};
}

std::optional<std::pair<std::size_t, std::size_t>> shard_of_array_task(const Slurm_array_task& task) {
  if (!task.id) return std::nullopt;
  const std::size_t id = number_of(*task.id, "SLURM_ARRAY_TASK_ID");
  if (!task.min)
    throw std::invalid_argument("SLURM_ARRAY_TASK_ID is set but SLURM_ARRAY_TASK_MIN is not: give --shard K/N");
  if (!task.max && !task.count)
    throw std::invalid_argument(
        "SLURM_ARRAY_TASK_ID is set but neither SLURM_ARRAY_TASK_MAX nor _COUNT is: give --shard K/N");
  const std::size_t min = number_of(*task.min, "SLURM_ARRAY_TASK_MIN");
  std::size_t shards = 0;
  if (task.max) {
    const std::size_t max = number_of(*task.max, "SLURM_ARRAY_TASK_MAX");
    if (max < min)
      throw std::invalid_argument("SLURM_ARRAY_TASK_MAX=" + *task.max + " is below SLURM_ARRAY_TASK_MIN=" + *task.min);
    shards = max - min + 1;
  }
  if (task.count) {
    const std::size_t count = number_of(*task.count, "SLURM_ARRAY_TASK_COUNT");
    if (shards != 0 && count != shards)
      throw std::invalid_argument("the array's " + *task.count + " tasks do not fill " + *task.min + ".." + *task.max +
                                  " (a list or a step): submit --array=A-B, or give --shard K/N");
    shards = count;
  }
  if (shards == 0) throw std::invalid_argument("SLURM_ARRAY_TASK_COUNT=0: an array of no tasks");
  if (id < min || id - min >= shards)
    throw std::invalid_argument("SLURM_ARRAY_TASK_ID=" + *task.id + " lies outside the array " + *task.min + ".." +
                                std::to_string(min + shards - 1));
  return std::pair(id - min + 1, shards);
}

std::pair<std::size_t, std::size_t> chosen_shard(const std::string& option, const Slurm_array_task& task) {
  if (!option.empty()) return parse_shard(option);
  return shard_of_array_task(task).value_or(std::pair<std::size_t, std::size_t>(1, 1));
}

}  // namespace curvebench::bench
