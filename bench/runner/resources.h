// Where curvebench finds the files it ships beside its code: the bundled data (data/, which
// the suites name as "data/...") and the report's scripts (bench/report/). They keep that
// layout both in the source tree and installed, under share/curvebench/.
#pragma once

#include <filesystem>

namespace curvebench::bench {

// The folder holding data/ and bench/report/. In order: $CURVEBENCH_ROOT when set; the
// root given to set_resource_root(); the source tree this library was built from.
std::filesystem::path resource_root();

// Makes `root` the resource root of this process (a program's main calls it once, before
// any job; $CURVEBENCH_ROOT still wins).
void set_resource_root(std::filesystem::path root);

// The root that belongs to the running executable: its ../share/curvebench when that holds
// data/ (an installed or unpacked curvebench), else `fallback`.
std::filesystem::path installed_root_or(std::filesystem::path fallback);

}  // namespace curvebench::bench
