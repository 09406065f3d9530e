#include "bench/runner/process_pool.h"

#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <system_error>
#include <utility>
#include <vector>

namespace curvebench::bench {
namespace {

using Clock = std::chrono::steady_clock;

// A worker process as the parent sees it. An answer is its length (8 bytes, native order:
// both ends are this program) and then its bytes.
struct Worker {
  pid_t pid;
  int socket;                        // the parent's end
  std::optional<std::size_t> task{};  // the task it runs, if any
  Clock::time_point deadline = Clock::time_point::max();
  std::string answer{};              // what it has sent of its answer so far
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

void reap(pid_t pid, int* status = nullptr) {
  while (waitpid(pid, status, 0) < 0 && errno == EINTR) {
  }
}

// Kills and reaps the workers still running when run_in_processes leaves, by an exception
// (an interruption, a failed fork, a `done` that threw) or not, so that none works on unseen.
struct Reaper {
  std::vector<Worker>& workers;
  ~Reaper() {
    for (const Worker& worker : workers) {
      kill(worker.pid, SIGKILL);
      close(worker.socket);
      reap(worker.pid);
    }
  }
};

// send() with MSG_NOSIGNAL: a peer that died is an error to handle, not a SIGPIPE that
// ends this process.
bool send_all(int socket, const void* data, std::size_t size) {
  const char* bytes = static_cast<const char*>(data);
  for (std::size_t sent = 0; sent < size;) {
    const ssize_t n = send(socket, bytes + sent, size - sent, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    sent += static_cast<std::size_t>(n);
  }
  return true;
}

bool receive_all(int socket, void* data, std::size_t size) {
  char* bytes = static_cast<char*>(data);
  for (std::size_t got = 0; got < size;) {
    const ssize_t n = recv(socket, bytes + got, size - got, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    got += static_cast<std::size_t>(n);
  }
  return true;
}

// The worker's loop: a task's index in, its answer out, until the parent closes its end.
[[noreturn]] void serve(int socket, const Process_pool_options& options,
                        const std::function<std::string(std::size_t)>& run) {
  if (options.memory_limit_bytes > 0) {
    const rlimit limit{options.memory_limit_bytes, options.memory_limit_bytes};
    setrlimit(RLIMIT_AS, &limit);
  }
  for (std::uint64_t task = 0; receive_all(socket, &task, sizeof task);) {
    const std::string output = run(task);
    const std::uint64_t size = output.size();
    if (!send_all(socket, &size, sizeof size) || !send_all(socket, output.data(), output.size())) _exit(3);
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

// No task ends its own process this way: these signals come from whoever stops the run
// (scancel sends SIGTERM to every process of a Slurm task, a terminal sends SIGINT to
// its foreground processes), and the parent may see its worker die before it gets its own.
bool stopped_from_outside(int status) {
  return WIFSIGNALED(status) && (WTERMSIG(status) == SIGTERM || WTERMSIG(status) == SIGINT || WTERMSIG(status) == SIGHUP);
}

std::string time_limit_text(double seconds) {
  char text[64];
  std::snprintf(text, sizeof text, "exceeded the time limit of %g s", seconds);
  return text;
}

// The whole answer in `received`, if it has come.
std::optional<std::string> complete_answer(std::string& received) {
  std::uint64_t size = 0;
  if (received.size() < sizeof size) return std::nullopt;
  std::memcpy(&size, received.data(), sizeof size);
  if (received.size() - sizeof size < size) return std::nullopt;
  return received.substr(sizeof size);
}

}  // namespace

Fork_hooks set_fork_hooks(Fork_hooks replacement) { return std::exchange(hooks(), std::move(replacement)); }

std::function<void()> set_interruption_check(std::function<void()> check) {
  return std::exchange(interruption_check(), std::move(check));
}

void run_in_processes(std::size_t count, const Process_pool_options& options,
                      const std::function<std::string(std::size_t)>& task,
                      const std::function<void(std::size_t, Task_outcome)>& done) {
  std::vector<Worker> workers;
  const Reaper reaper{workers};
  const std::function<void()>& check = interruption_check();
  std::size_t next = 0;  // the first task not yet sent
  const auto timeout = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.timeout_seconds));

  const auto start_worker = [&] {
    int ends[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0)
      throw std::system_error(errno, std::generic_category(), "socketpair");
    std::fflush(nullptr);  // or the worker would flush the parent's buffered output again
    const Fork_hooks& around = hooks();
    if (around.before) around.before();
    const pid_t pid = fork();
    const int fork_error = errno;
    if (pid != 0 && around.after_parent) around.after_parent();
    if (pid < 0) {
      close(ends[0]), close(ends[1]);
      throw std::system_error(fork_error, std::generic_category(), "fork");
    }
    if (pid == 0) {
      if (around.after_child) around.after_child();
      close(ends[0]);
      // A sibling must see the end of its tasks when the parent closes its socket, so no
      // other process may hold that socket open.
      for (const Worker& other : workers) close(other.socket);
      serve(ends[1], options, task);
    }
    close(ends[1]);
    workers.push_back({.pid = pid, .socket = ends[0]});
  };
  // Gives worker k the next task; without one, closes its socket, which ends it.
  const auto send_next = [&](std::size_t k) {
    Worker& worker = workers[k];
    if (next == count) {
      close(worker.socket);
      reap(worker.pid);
      workers.erase(workers.begin() + static_cast<std::ptrdiff_t>(k));
      return;
    }
    const std::uint64_t index = next;
    worker.task = next++;
    worker.deadline = options.timeout_seconds > 0 ? Clock::now() + timeout : Clock::time_point::max();
    worker.answer.clear();
    // A worker that died between two tasks fails this send; poll then sees its socket's
    // end, and the task counts as crashed with the worker's exit status.
    send_all(worker.socket, &index, sizeof index);
  };
  // Worker k's task ended without an answer: the worker is killed (if it still runs),
  // reaped and replaced while tasks are left.
  const auto lose = [&](std::size_t k, Task_outcome outcome) {
    Worker worker = std::move(workers[k]);
    workers.erase(workers.begin() + static_cast<std::ptrdiff_t>(k));
    if (outcome.kind == Task_outcome::Kind::timed_out) kill(worker.pid, SIGKILL);
    close(worker.socket);
    int status = 0;
    reap(worker.pid, &status);
    if (outcome.kind == Task_outcome::Kind::crashed && stopped_from_outside(status))
      throw Run_stopped("a worker was " + describe(status) + ": the run stops; --resume runs the rest");
    if (outcome.kind == Task_outcome::Kind::crashed) outcome.reason = describe(status);
    if (next < count) {
      start_worker();
      send_next(workers.size() - 1);
    }
    done(*worker.task, std::move(outcome));
  };

  for (std::size_t k = 0; k < std::min(std::max<std::size_t>(options.workers, 1), count); ++k) {
    start_worker();
    send_next(k);
  }
  while (!workers.empty()) {
    std::vector<pollfd> polled;
    auto wait = Clock::duration::max();
    for (const Worker& worker : workers) {
      polled.push_back({worker.socket, POLLIN, 0});
      wait = std::min(wait, worker.deadline - Clock::now());
    }
    int wait_ms = wait == Clock::duration::max()
                      ? -1
                      : static_cast<int>(std::max<long long>(
                            0, std::chrono::duration_cast<std::chrono::milliseconds>(wait).count() + 1));
    if (check && (wait_ms < 0 || wait_ms > check_interval_ms)) wait_ms = check_interval_ms;
    if (poll(polled.data(), polled.size(), wait_ms) < 0 && errno != EINTR)
      throw std::system_error(errno, std::generic_category(), "poll");
    if (check) check();  // an interrupt seen by poll (EINTR) is seen here at once

    // Backwards, so that removing a worker does not move the ones still to look at (a
    // replacement goes to the back, unpolled this round).
    for (std::size_t k = polled.size(); k-- > 0;) {
      Worker& worker = workers[k];
      if (polled[k].revents != 0) {
        char buffer[65536];
        const ssize_t n = recv(worker.socket, buffer, sizeof buffer, 0);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
          lose(k, {Task_outcome::Kind::crashed, "", ""});  // the end of its socket: it died
          continue;
        }
        worker.answer.append(buffer, static_cast<std::size_t>(n));
        if (std::optional<std::string> answer = complete_answer(worker.answer)) {
          const std::size_t finished = *worker.task;
          send_next(k);
          done(finished, {Task_outcome::Kind::finished, std::move(*answer), ""});
        }
      } else if (Clock::now() >= worker.deadline) {
        lose(k, {Task_outcome::Kind::timed_out, "", time_limit_text(options.timeout_seconds)});
      }
    }
  }
}

}  // namespace curvebench::bench
