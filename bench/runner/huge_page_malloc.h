// Restarts the program once with glibc's malloc backing its heap by transparent huge pages.
//
// Why: at 10^6 points a Delaunay triangulation touches about 300 MB of fresh memory, and
// the kernel faults it in 4 KB at a time; under a hypervisor that was a third of the run
// (docs/development.md, "Speed at 10^6 points"). With 2 MB pages the triangulation and
// the algorithms built on it ran 1.9-2.9x faster there. Linux grants huge pages to a
// process only where it asks (the usual setting, transparent_hugepage=madvise), and glibc
// asks only when the tunable glibc.malloc.hugetlb=1 is set before the program starts:
// hence the restart.
//
// Nothing restarts when GLIBC_TUNABLES already names glibc.malloc.hugetlb (so
// GLIBC_TUNABLES=glibc.malloc.hugetlb=0 turns this off) or when the restart fails; the
// program then runs as it would have. Call first thing in main, before any thread starts.
#pragma once

#include <unistd.h>

#include <cstdlib>
#include <string>

namespace curvebench::bench {

/// Re-executes this program (same arguments, same process id) with
/// glibc.malloc.hugetlb=1 added to GLIBC_TUNABLES, unless that tunable is already set.
/// Returns only if it did not re-execute.
inline void restart_with_huge_page_malloc(char** argv) {
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  std::string value = tunables ? tunables : "";
  if (value.find("glibc.malloc.hugetlb") != std::string::npos) return;
  value += value.empty() ? "glibc.malloc.hugetlb=1" : ":glibc.malloc.hugetlb=1";
  if (setenv("GLIBC_TUNABLES", value.c_str(), 1) != 0) return;
  execv("/proc/self/exe", argv);
}

}  // namespace curvebench::bench
