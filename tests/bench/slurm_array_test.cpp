// The shard of a Slurm array task, from SLURM_ARRAY_TASK_ID, _MIN, _MAX and _COUNT.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "bench/runner/slurm_array.h"

namespace curvebench::bench {
namespace {

using Shard = std::pair<std::size_t, std::size_t>;

// The message of the std::invalid_argument `task` gives, or "" if it gives none.
std::string error_of(const Slurm_array_task& task) {
  try {
    shard_of_array_task(task);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(SlurmArray, OutsideAnArrayThereIsNoShard) {
  EXPECT_EQ(shard_of_array_task({}), std::nullopt);
  EXPECT_EQ(shard_of_array_task({.min = "1", .max = "4"}), std::nullopt) << "no ID: not an array task";
  EXPECT_EQ(chosen_shard("", {}), Shard(1, 1)) << "the whole run";
}

TEST(SlurmArray, TheTaskIsItsPlaceInTheRange) {
  EXPECT_EQ(shard_of_array_task({.id = "1", .min = "1", .max = "4", .count = "4"}), Shard(1, 4));
  EXPECT_EQ(shard_of_array_task({.id = "4", .min = "1", .max = "4", .count = "4"}), Shard(4, 4));
  EXPECT_EQ(shard_of_array_task({.id = "0", .min = "0", .max = "7"}), Shard(1, 8)) << "--array=0-7";
  EXPECT_EQ(shard_of_array_task({.id = "12", .min = "10", .count = "5"}), Shard(3, 5)) << "COUNT without MAX";
  EXPECT_EQ(shard_of_array_task({.id = "5", .min = "5", .max = "5", .count = "1"}), Shard(1, 1));
}

TEST(SlurmArray, AGivenShardWins) {
  EXPECT_EQ(chosen_shard("2/3", {.id = "1", .min = "1", .max = "4"}), Shard(2, 3));
  EXPECT_EQ(chosen_shard("", {.id = "3", .min = "1", .max = "4"}), Shard(3, 4));
  EXPECT_THROW(chosen_shard("2-3", {}), std::invalid_argument);
}

TEST(SlurmArray, BadValuesAreClearErrors) {
  EXPECT_NE(error_of({.id = "5", .min = "1", .max = "4"}).find("outside the array 1..4"), std::string::npos);
  EXPECT_NE(error_of({.id = "0", .min = "1", .max = "4"}).find("outside"), std::string::npos);
  EXPECT_NE(error_of({.id = "7", .min = "1", .count = "4"}).find("outside the array 1..4"), std::string::npos);
  EXPECT_NE(error_of({.id = "1", .max = "4"}).find("SLURM_ARRAY_TASK_MIN is not"), std::string::npos);
  EXPECT_NE(error_of({.id = "1", .min = "1"}).find("neither SLURM_ARRAY_TASK_MAX nor _COUNT"), std::string::npos);
  // --array=1,5,9 or 1-9:4: three tasks that do not fill 1..9.
  EXPECT_NE(error_of({.id = "5", .min = "1", .max = "9", .count = "3"}).find("do not fill 1..9"), std::string::npos);
  EXPECT_NE(error_of({.id = "2", .min = "4", .max = "1"}).find("below"), std::string::npos);
  EXPECT_NE(error_of({.id = "1", .min = "1", .count = "0"}).find("no tasks"), std::string::npos);
  for (const char* bad : {"", "x", "3x", "-1", " 2", "2.0", "99999999999999999999999"})
    EXPECT_NE(error_of({.id = bad, .min = "1", .max = "4"}).find("SLURM_ARRAY_TASK_ID='" + std::string(bad) + "' is not"),
              std::string::npos)
        << bad;
  EXPECT_NE(error_of({.id = "1", .min = "one", .max = "4"}).find("SLURM_ARRAY_TASK_MIN='one'"), std::string::npos);
  EXPECT_NE(error_of({.id = "1", .min = "1", .max = "4", .count = "four"}).find("SLURM_ARRAY_TASK_COUNT"), std::string::npos);
}

TEST(SlurmArray, ReadsTheEnvironment) {
  setenv("SLURM_ARRAY_TASK_ID", "6", 1);
  setenv("SLURM_ARRAY_TASK_MIN", "5", 1);
  setenv("SLURM_ARRAY_TASK_MAX", "8", 1);
  unsetenv("SLURM_ARRAY_TASK_COUNT");
  const Slurm_array_task task = slurm_array_task_from_environment();
  EXPECT_EQ(shard_of_array_task(task), Shard(2, 4));
  EXPECT_EQ(task.count, std::nullopt);
  for (const char* name : {"SLURM_ARRAY_TASK_ID", "SLURM_ARRAY_TASK_MIN", "SLURM_ARRAY_TASK_MAX"}) unsetenv(name);
}

}  // namespace
}  // namespace curvebench::bench
