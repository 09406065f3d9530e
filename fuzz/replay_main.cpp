// A plain main() for the fuzz targets in the normal build: it runs LLVMFuzzerTestOneInput
// on every file named on the command line or found below a directory named there, so
// the committed corpora and regressions replay as ctest tests under any compiler, and a
// finding can be stepped through in a debugger without libFuzzer.
//
//   replay_NAME PATH...
//
// A path that does not exist counts as an empty directory (a target may have no
// regressions yet), but replaying nothing at all fails, so a mistyped path is noticed.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "fuzz/fuzz_target.h"

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> input_files(const fs::path& path) {
  if (!fs::is_directory(path)) return fs::is_regular_file(path) ? std::vector{path} : std::vector<fs::path>{};
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(path))
    if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());  // a stable order, so a log points at the same input
  return files;
}

void replay(const fs::path& file) {
  std::fprintf(stderr, "replaying %s\n", file.c_str());
  std::ifstream in(file, std::ios::binary);
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t replayed = 0;
  for (int i = 1; i < argc; ++i)
    for (const fs::path& file : input_files(argv[i])) {
      replay(file);
      ++replayed;
    }
  if (replayed == 0) {
    std::fprintf(stderr, "replay: no input file in the paths given\n");
    return 1;
  }
  std::printf("replayed %zu inputs, no finding\n", replayed);
  return 0;
}
