#include "bench/cli/slurm_command.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/runner/suite.h"

namespace curvebench::cli {
namespace {

namespace fs = std::filesystem;

struct Slurm_options {
  fs::path output;
  std::size_t tasks = 0;
  std::string partition, time;
  std::size_t cpus = 1;
  bool submit = false;
  std::vector<std::string> command;  // run SUITE ..., certify ... or rate ...: the words after `slurm`
};

// `text` as one word of a POSIX shell: single-quoted unless it is plainly safe.
std::string shell_word(const std::string& text) {
  const bool plain = !text.empty() && std::ranges::all_of(text, [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || std::string_view("-_./=,:+@%").find(c) != std::string_view::npos;
  });
  if (plain) return text;
  std::string quoted = "'";
  for (const char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string shell_words(const std::vector<std::string>& words) {
  std::string line;
  for (const std::string& word : words) line += (line.empty() ? "" : " ") + shell_word(word);
  return line;
}

bool has_word(const std::vector<std::string>& words, std::string_view word) {
  return std::ranges::any_of(words, [&](const std::string& w) { return w == word || w.starts_with(std::string(word) + "="); });
}

// The value of `--name VALUE` or `--name=VALUE` among `words`, or "".
std::string value_of(const std::vector<std::string>& words, std::string_view name) {
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (words[i] == name && i + 1 < words.size()) return words[i + 1];
    if (words[i].starts_with(std::string(name) + "=")) return words[i].substr(name.size() + 1);
  }
  return "";
}

// The command's words, checked: one of the three commands, a known suite, and none of the
// options the scripts set themselves.
void check_command(const std::vector<std::string>& command) {
  if (command.empty() || (command[0] != "run" && command[0] != "certify" && command[0] != "rate"))
    throw std::invalid_argument("slurm: give the command to shard: run SUITE ..., certify ... or rate ...");
  if (command[0] == "run" && (command.size() < 2 || !bench::find_suite(command[1])))
    throw std::invalid_argument("slurm run: unknown or missing suite" +
                                (command.size() > 1 ? " '" + command[1] + "'" : std::string()) +
                                " (see `curvebench list suites`)");
  for (const char* own : {"--shard", "--resume", "-j", "--jobs", "-o", "--output"})
    if (has_word(command, own))
      throw std::invalid_argument(std::string("slurm: the scripts set ") + own +
                                  " themselves (-o DIR and --cpus C are the slurm command's)");
}

std::string header(const std::string& job_name, const Slurm_options& o, const fs::path& log) {
  std::ostringstream s;
  s << "#SBATCH --job-name=" << job_name << '\n';
  s << "#SBATCH --cpus-per-task=" << o.cpus << '\n';
  if (!o.time.empty()) s << "#SBATCH --time=" << o.time << '\n';
  if (!o.partition.empty()) s << "#SBATCH --partition=" << o.partition << '\n';
  s << "#SBATCH --chdir=" << fs::current_path().string() << '\n';
  s << "#SBATCH --output=" << log.string() << '\n';
  return s.str();
}

std::string array_script(const Slurm_options& o, const fs::path& curvebench) {
  const std::string n = std::to_string(o.tasks), what = shell_words(o.command);
  const fs::path dir = o.output, scripts = dir / "slurm";
  std::vector<std::string> options = {"--resume"};
  // Shards are quiet (progress lines would fill the logs) and draw no report: the merge does.
  for (const char* option : {"-q", "--no-report"})
    if ((o.command[0] == "run" || std::string_view(option) == "-q") && !has_word(o.command, option))
      options.push_back(option);
  std::ostringstream s;
  s << "#!/bin/bash\n"
    << "# curvebench " << what << "\n"
    << "# as a Slurm job array of " << n << " tasks: task K runs shard K/" << n << " into " << (dir / "shard-K").string()
    << ".\n"
    << "# Written by `curvebench slurm`; adapt the #SBATCH lines to your site.\n"
    << "# --resume: a task that was preempted, requeued or resubmitted continues where it\n"
    << "# stopped and loses no row. The shard is spelled out (not read from the array's\n"
    << "# MIN/MAX) so that one task can be run again alone:\n"
    << "#   sbatch --array=K " << shell_word((scripts / "array.sbatch").string()) << '\n'
    << "#SBATCH --array=1-" << n << '\n'
    << header("curvebench-" + o.command[0], o, scripts / "logs" / "array-%A_%a.out")
    << "#SBATCH --requeue\n"
    << "#SBATCH --open-mode=append\n"
    << "set -euo pipefail\n"
    << "shard=$SLURM_ARRAY_TASK_ID\n"
    << "exec " << shell_word(curvebench.string()) << ' ' << what << " \\\n"
    << "  -o " << shell_word(dir.string()) << "/shard-\"$shard\" --shard \"$shard/" << n << "\" -j \"${SLURM_CPUS_PER_TASK:-"
    << o.cpus << "}\" " << shell_words(options) << '\n';
  return s.str();
}

std::string merge_script(const Slurm_options& o, const fs::path& curvebench) {
  const std::string n = std::to_string(o.tasks), what = shell_words(o.command);
  const std::string exe = shell_word(curvebench.string()), dir = shell_word(o.output.string());
  const fs::path scripts = o.output / "slurm";
  const std::string shards = dir + "/shard-{1.." + n + "}";
  const std::string cpus = "-j \"${SLURM_CPUS_PER_TASK:-" + std::to_string(o.cpus) + "}\"";
  std::ostringstream s;
  s << "#!/bin/bash\n"
    << "# Merges the " << n << " shards of " << shell_word((scripts / "array.sbatch").string()) << " into " << dir << ",\n"
    << "# after the array succeeded: `curvebench slurm --submit` submits it as\n"
    << "#   sbatch --dependency=afterok:ARRAY_JOB " << shell_word((scripts / "merge.sbatch").string()) << '\n'
    << "# `curvebench merge` refuses shards of another run and names missing or unfinished ones.\n"
    << header("curvebench-" + o.command[0] + "-merge", o, scripts / "logs" / "merge-%j.out")
    << "set -euo pipefail\n";
  if (o.command[0] == "run") {
    std::vector<std::string> merge_options;
    if (const std::string pictures = value_of(o.command, "--pictures"); !pictures.empty())
      merge_options = {"--pictures", pictures};
    if (has_word(o.command, "--no-report")) merge_options.push_back("--no-report");
    s << exe << " merge -o " << dir << (merge_options.empty() ? "" : " " + shell_words(merge_options)) << ' ' << shards
      << '\n';
  } else {
    // The merged directory is the whole run: the command resumed on it runs no job again
    // but writes what it writes at the end, the certification's summary and
    // counterexamples or the rate table.
    s << "# The merged directory holds every job, so the command resumed on it runs none\n"
      << "# again and only writes its summary.\n";
    const std::string pictures = o.command[0] == "certify" ? "failures" : "none";
    s << exe << " merge --no-report --pictures " << pictures << " -o " << dir << ' ' << shards << '\n';
    const fs::path summary = o.output / (o.command[0] == "certify" ? "certify.json" : "rate.txt");
    s << exe << ' ' << what << " -o " << dir << " --resume " << cpus
      << (o.command[0] == "certify" && !has_word(o.command, "--json") ? " --json" : "") << " > "
      << shell_word(summary.string()) << '\n';
  }
  return s.str();
}

// Runs `sbatch --parsable ARGS...` and returns the job id it prints ("ID" or "ID;CLUSTER").
std::string submit(const std::vector<std::string>& arguments) {
  const std::string line = "sbatch --parsable " + shell_words(arguments);
  std::fflush(nullptr);
  FILE* pipe = popen(line.c_str(), "r");
  if (!pipe) throw std::runtime_error("slurm: cannot run sbatch");
  std::string out;
  std::array<char, 256> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe)) out += buffer.data();
  const int status = pclose(pipe);
  const std::string id = out.substr(0, out.find_first_of(";\n"));
  if (status != 0 || id.empty() || !std::ranges::all_of(id, [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
    throw std::runtime_error("slurm: `" + line + "` failed" + (out.empty() ? std::string() : ": " + out));
  return id;
}

void write_scripts(Slurm_options& o) {
  check_command(o.command);
  if (o.tasks == 0) throw std::invalid_argument("slurm: --tasks must be at least 1");
  if (o.cpus == 0) throw std::invalid_argument("slurm: --cpus must be at least 1");
  o.output = fs::absolute(o.output).lexically_normal();
  const fs::path curvebench = fs::read_symlink("/proc/self/exe");
  const fs::path scripts = o.output / "slurm";
  fs::create_directories(scripts / "logs");  // Slurm opens the --output files there before the job runs
  const fs::path array = scripts / "array.sbatch", merge = scripts / "merge.sbatch";
  std::ofstream(array) << array_script(o, curvebench);
  std::ofstream(merge) << merge_script(o, curvebench);
  for (const fs::path& script : {array, merge})
    fs::permissions(script, fs::perms::owner_exec | fs::perms::group_exec, fs::perm_options::add);
  std::cerr << "slurm: wrote " << array.string() << " (" << o.tasks << " tasks) and " << merge.string() << '\n';
  if (!o.submit) {
    std::cerr << "submit: id=$(sbatch --parsable " << shell_word(array.string()) << ") && sbatch --dependency=afterok:$id "
              << shell_word(merge.string()) << '\n';
    return;
  }
  const std::string array_id = submit({array.string()});
  std::string merge_id;
  try {
    merge_id = submit({"--dependency=afterok:" + array_id, merge.string()});
  } catch (const std::runtime_error& error) {
    throw std::runtime_error(std::string(error.what()) + " (the array is submitted: job " + array_id + ")");
  }
  std::cout << "array job " << array_id << '\n' << "merge job " << merge_id << '\n';
  // afterok never holds once a task has failed for good: the merge then waits forever.
  std::cerr << "if a task K fails for good: scancel " << merge_id << "; id=$(sbatch --parsable --array=K "
            << shell_word(array.string()) << ") && sbatch --dependency=afterok:$id " << shell_word(merge.string()) << '\n';
}

}  // namespace

void add_slurm_command(CLI::App& app) {
  auto o = std::make_shared<Slurm_options>();
  CLI::App* command = app.add_subcommand(
      "slurm", "Write (and --submit) Slurm batch scripts that run `run`, `certify` or `rate` as a job array of "
               "shards and merge them: curvebench slurm run SUITE [-a ...] -o DIR --tasks N");
  command->allow_extras();  // the words of the command to shard, passed on as they are
  command->add_option("-o,--output", o->output, "Directory of the merged results; shards in DIR/shard-K, scripts and "
                                                "logs in DIR/slurm")
      ->required();
  command->add_option("--tasks", o->tasks, "Array tasks, i.e. shards")->required();
  command->add_option("--partition", o->partition, "Slurm partition (default: the cluster's)");
  command->add_option("--time", o->time, "Time limit per task, as sbatch --time takes it (e.g. 2:00:00)");
  command->add_option("--cpus", o->cpus, "CPUs per task: the worker processes of each shard")->capture_default_str();
  command->add_flag("--submit", o->submit, "Submit both scripts with sbatch and print the job ids");
  command->callback([o, command] {
    o->command = command->remaining();
    write_scripts(*o);
  });
}

}  // namespace curvebench::cli
