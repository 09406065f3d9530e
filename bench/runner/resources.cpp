#include "bench/runner/resources.h"

#include <cstdlib>
#include <system_error>

namespace curvebench::bench {
namespace {

std::filesystem::path& chosen_root() {
  static std::filesystem::path root = CURVEBENCH_SOURCE_DIR;
  return root;
}

}  // namespace

std::filesystem::path resource_root() {
  if (const char* root = std::getenv("CURVEBENCH_ROOT"); root != nullptr && *root != '\0') return root;
  return chosen_root();
}

void set_resource_root(std::filesystem::path root) { chosen_root() = std::move(root); }

std::filesystem::path installed_root_or(std::filesystem::path fallback) {
  std::error_code error;
  const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) return fallback;
  const std::filesystem::path installed = executable.parent_path().parent_path() / "share" / "curvebench";
  return std::filesystem::is_directory(installed / "data", error) ? installed : fallback;
}

}  // namespace curvebench::bench
