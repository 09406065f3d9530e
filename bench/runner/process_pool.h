// Runs tasks in worker processes, a few at a time, so that a task that crashes (a
// segfault, an abort, std::terminate), runs out of memory or exceeds its time limit costs
// only itself: the caller learns what happened and goes on. Threads could not give that
// isolation; a crash in a thread ends the whole run.
//
// A worker is forked once and runs task after task: the parent sends it a task's index
// over a socket, it runs `task(i)` and sends back the string it returns. A worker that
// dies or is killed at the time limit is replaced by a fresh fork for the tasks left.
// Forking once per task cost more than most tasks (the benchmark's jobs take a few
// milliseconds; a fork of the runner, with its inputs, and the copy-on-write faults after
// it took about as long again), so tasks must not depend on state an earlier task of the
// same worker left: the runner's determinism test (cli.determinism) checks that its jobs
// do not, by comparing runs with one and two workers.
//
// A worker leaves with _exit (no atexit handlers, no stdio flush of the parent's buffers).
// It must not use threads that the parent started (oneTBB's workers are not copied by
// fork): tasks are single-threaded.
#pragma once

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>

namespace curvebench::bench {

// How one task ended.
struct Task_outcome {
  // finished: it returned; crashed: its worker died or exited before it returned;
  // timed_out: it was killed at the time limit.
  enum class Kind { finished, crashed, timed_out };
  Kind kind = Kind::finished;  // how it ended
  std::string output;  // what the task returned (finished), else empty
  std::string reason;  // crashed / timed out: "killed by signal 11 (Segmentation fault)", ...
};

// How many children run at once, and the limits of each.
struct Process_pool_options {
  std::size_t workers = 1;      // worker processes at once
  double timeout_seconds = 0;   // per task; 0: none
  std::size_t memory_limit_bytes = 0;  // address-space limit of each worker; 0: none
};

// Calls made around each fork() of run_in_processes, for a host process whose own state
// must be made safe to fork: an embedded interpreter (python/ takes Python's GIL and runs
// PyOS_BeforeFork and PyOS_AfterFork_Parent or _Child, as os.fork() does). An empty
// function is no call.
struct Fork_hooks {
  std::function<void()> before;        // in the parent, just before fork()
  std::function<void()> after_parent;  // in the parent, just after fork(), also when it failed
  std::function<void()> after_child;   // in the child, before anything else
};

// Makes `hooks` those of every later fork of run_in_processes in this process (not of the
// programs that exec: algorithms start, which exec at once); returns the hooks it replaces.
Fork_hooks set_fork_hooks(Fork_hooks hooks);

// Makes `check` the interruption check of every later run_in_processes in this process
// (an empty function: none); returns the check it replaces. The check is called in the
// parent at least every 100 ms while tasks run; an exception it throws ends
// run_in_processes: for a host that must see its user's interrupt (python/ raises
// KeyboardInterrupt on Ctrl-C).
std::function<void()> set_interruption_check(std::function<void()> check);

// Thrown when a worker was stopped from outside (SIGTERM, SIGINT or SIGHUP: scancel, a
// preempted Slurm task, Ctrl-C in a terminal): the whole run is being stopped, so its task
// gets no outcome (a resumed run runs it again) rather than a "crashed" one.
struct Run_stopped : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Runs task(0) ... task(count - 1), in that order, in at most options.workers worker
// processes; calls done(i, outcome) in the parent as each ends, in the order they end.
// Throws std::system_error if a socket or process cannot be made, Run_stopped if a
// worker was stopped from outside, and passes on what the interruption check or `done`
// throws; when it throws, the workers still running are killed and reaped first, so that
// none works on unseen.
void run_in_processes(std::size_t count, const Process_pool_options& options,
                      const std::function<std::string(std::size_t)>& task,
                      const std::function<void(std::size_t, Task_outcome)>& done);

}  // namespace curvebench::bench
