// bench/runner/huge_page_malloc.h: the program restarts itself once with
// glibc.malloc.hugetlb=1 added to GLIBC_TUNABLES, keeping other tunables and its arguments,
// and does not restart when the tunable is already named. The restarted program is this
// test binary, running only DISABLED_ReportsItsTunables, which prints what it was given.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

#include "bench/runner/huge_page_malloc.h"

namespace curvebench::bench {
namespace {

// Run in the restarted process only (never by default: it is disabled).
TEST(HugePageMalloc, DISABLED_ReportsItsTunables) {
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  std::printf("restarted with GLIBC_TUNABLES=%s\n", tunables ? tunables : "(unset)");
}

// In a child process with GLIBC_TUNABLES = `tunables` (nullopt: unset), calls
// restart_with_huge_page_malloc and returns what the child printed.
std::string child_output(const std::optional<std::string>& tunables) {
  int pipe_ends[2];
  EXPECT_EQ(pipe(pipe_ends), 0);
  const pid_t child = fork();
  if (child == 0) {
    dup2(pipe_ends[1], STDOUT_FILENO);
    close(pipe_ends[0]);
    if (tunables)
      setenv("GLIBC_TUNABLES", tunables->c_str(), 1);
    else
      unsetenv("GLIBC_TUNABLES");
    char self[] = "/proc/self/exe", filter[] = "--gtest_filter=HugePageMalloc.DISABLED_ReportsItsTunables",
         disabled[] = "--gtest_also_run_disabled_tests", brief[] = "--gtest_brief=1";
    char* argv[] = {self, filter, disabled, brief, nullptr};
    restart_with_huge_page_malloc(argv);
    std::printf("not restarted\n");
    std::fflush(stdout);
    _exit(0);
  }
  close(pipe_ends[1]);
  std::string output;
  char buffer[4096];
  for (ssize_t got; (got = read(pipe_ends[0], buffer, sizeof buffer)) > 0;) output.append(buffer, std::size_t(got));
  close(pipe_ends[0]);
  int status = 0;
  waitpid(child, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << output;
  return output;
}

TEST(HugePageMalloc, RestartsWithTheTunableAdded) {
  EXPECT_NE(child_output(std::nullopt).find("restarted with GLIBC_TUNABLES=glibc.malloc.hugetlb=1\n"),
            std::string::npos);
  EXPECT_NE(child_output("glibc.malloc.check=0").find(
                "restarted with GLIBC_TUNABLES=glibc.malloc.check=0:glibc.malloc.hugetlb=1\n"),
            std::string::npos);
}

TEST(HugePageMalloc, KeepsAChoiceAlreadyMade) {
  EXPECT_EQ(child_output("glibc.malloc.hugetlb=0"), "not restarted\n");
}

}  // namespace
}  // namespace curvebench::bench
