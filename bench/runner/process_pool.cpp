#include "bench/runner/process_pool.h"

#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <system_error>
#include <utility>
#include <vector>

namespace curvebench::bench {
namespace {

using Clock = std::chrono::steady_clock;

struct Child {
  std::size_t task;
  pid_t pid;
  int pipe;  // read end
  Clock::time_point deadline;
  std::string output;
};

Fork_hooks& hooks() {
  static Fork_hooks hooks;
  return hooks;
}

std::function<void()>& interruption_check() {
  static std::function<void()> check;
  return check;
}

// The longest wait between two interruption checks.
constexpr int check_interval_ms = 100;

// Kills and reaps the children still running when run_in_processes leaves by an exception
// (an interruption, a failed fork, a `done` that threw), so that none works on unseen.
struct Reaper {
  std::vector<Child>& running;
  ~Reaper() {
    for (const Child& child : running) {
      kill(child.pid, SIGKILL);
      close(child.pipe);
      while (waitpid(child.pid, nullptr, 0) < 0 && errno == EINTR) {
      }
    }
  }
};

[[noreturn]] void run_child(std::size_t task, int pipe, const Process_pool_options& options,
                            const std::function<std::string(std::size_t)>& run) {
  if (options.memory_limit_bytes > 0) {
    const rlimit limit{options.memory_limit_bytes, options.memory_limit_bytes};
    setrlimit(RLIMIT_AS, &limit);
  }
  const std::string output = run(task);
  for (std::size_t sent = 0; sent < output.size();) {
    const ssize_t n = write(pipe, output.data() + sent, output.size() - sent);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) _exit(3);
    sent += static_cast<std::size_t>(n);
  }
  _exit(0);
}

std::string describe(int status) {
  if (WIFSIGNALED(status)) {
    const int signal = WTERMSIG(status);
    return "killed by signal " + std::to_string(signal) + " (" + strsignal(signal) + ")";
  }
  if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status)) + " without a result";
  return "ended abnormally";
}

std::string time_limit_text(double seconds) {
  char text[64];
  std::snprintf(text, sizeof text, "exceeded the time limit of %g s", seconds);
  return text;
}

}  // namespace

Fork_hooks set_fork_hooks(Fork_hooks replacement) { return std::exchange(hooks(), std::move(replacement)); }

std::function<void()> set_interruption_check(std::function<void()> check) {
  return std::exchange(interruption_check(), std::move(check));
}

void run_in_processes(std::size_t count, const Process_pool_options& options,
                      const std::function<std::string(std::size_t)>& task,
                      const std::function<void(std::size_t, Task_outcome)>& done) {
  std::vector<Child> running;
  const Reaper reaper{running};
  const std::function<void()>& check = interruption_check();
  std::size_t next = 0;
  const auto timeout = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.timeout_seconds));
  const auto finish = [&](std::size_t k, Task_outcome outcome) {
    Child child = std::move(running[k]);
    running.erase(running.begin() + static_cast<std::ptrdiff_t>(k));
    close(child.pipe);
    int status = 0;
    if (outcome.kind == Task_outcome::Kind::timed_out) kill(child.pid, SIGKILL);
    while (waitpid(child.pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (outcome.kind == Task_outcome::Kind::finished) {
      if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && !child.output.empty())
        outcome.output = std::move(child.output);
      else
        outcome = {Task_outcome::Kind::crashed, "", describe(status)};
    }
    done(child.task, std::move(outcome));
  };

  while (next < count || !running.empty()) {
    while (next < count && running.size() < std::max<std::size_t>(options.workers, 1)) {
      int fds[2];
      if (pipe(fds) != 0) throw std::system_error(errno, std::generic_category(), "pipe");
      std::fflush(nullptr);  // or the child would flush the parent's buffered output again
      const Fork_hooks& around = hooks();
      if (around.before) around.before();
      const pid_t pid = fork();
      const int fork_error = errno;
      if (pid != 0 && around.after_parent) around.after_parent();
      if (pid < 0) {
        close(fds[0]), close(fds[1]);
        throw std::system_error(fork_error, std::generic_category(), "fork");
      }
      if (pid == 0) {
        if (around.after_child) around.after_child();
        close(fds[0]);
        for (const Child& other : running) close(other.pipe);
        run_child(next, fds[1], options, task);
      }
      close(fds[1]);
      running.push_back({next++, pid, fds[0], options.timeout_seconds > 0 ? Clock::now() + timeout : Clock::time_point::max(), {}});
    }

    std::vector<pollfd> polled;
    auto wait = Clock::duration::max();
    for (const Child& child : running) {
      polled.push_back({child.pipe, POLLIN, 0});
      wait = std::min(wait, child.deadline - Clock::now());
    }
    int wait_ms = wait == Clock::duration::max()
                      ? -1
                      : static_cast<int>(std::max<long long>(
                            0, std::chrono::duration_cast<std::chrono::milliseconds>(wait).count() + 1));
    if (check && (wait_ms < 0 || wait_ms > check_interval_ms)) wait_ms = check_interval_ms;
    if (poll(polled.data(), polled.size(), wait_ms) < 0 && errno != EINTR)
      throw std::system_error(errno, std::generic_category(), "poll");
    if (check) check();  // an interrupt seen by poll (EINTR) is seen here at once

    // Backwards, so that finishing a child does not move the ones still to look at.
    for (std::size_t k = running.size(); k-- > 0;) {
      if (polled[k].revents != 0) {
        char buffer[65536];
        const ssize_t n = read(running[k].pipe, buffer, sizeof buffer);
        if (n > 0) {
          running[k].output.append(buffer, static_cast<std::size_t>(n));
          continue;
        }
        if (n < 0 && errno == EINTR) continue;
        finish(k, {});  // end of file: the child is done
      } else if (Clock::now() >= running[k].deadline) {
        finish(k, {Task_outcome::Kind::timed_out, "",
                   time_limit_text(options.timeout_seconds)});
      }
    }
  }
}

}  // namespace curvebench::bench
