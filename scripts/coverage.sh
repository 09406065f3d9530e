#!/usr/bin/env bash
# Line and branch coverage of geometry/, graphs/ and algorithms/ by the whole ctest run
# (the unit tests, properties, command-line checks and every fuzz corpus replay), with
# clang's source-based coverage. Prints one row per folder, then one per file of
# algorithms/, lowest line coverage first.
#
#   scripts/coverage.sh            build build-coverage/, run ctest there, print the tables
#   scripts/coverage.sh --report   print the tables of the last run again
#
# Packages as for the tests (scripts/setup.sh); llvm-cov and llvm-profdata come with clang-14.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$root/build-coverage
profiles=$build/profiles

if [[ "${1:-}" != --report ]]; then
  "$root/scripts/setup.sh" test
  flags="-fprofile-instr-generate -fcoverage-mapping"
  CXX=clang++-14 cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="$flags" -DCURVEBENCH_BENCHMARKS=OFF >/dev/null
  cmake --build "$build" -j"$(nproc)"
  rm -rf "$profiles" && mkdir -p "$profiles"
  # %p: one file per process (tests start the command and its worker processes); %m: per binary.
  (cd "$build" && LLVM_PROFILE_FILE="$profiles/%m-%p.profraw" ctest -j"$(nproc)" --output-on-failure) || true
  find "$profiles" -name '*.profraw' >"$build/profiles.list"
  llvm-profdata-14 merge -sparse -f "$build/profiles.list" -o "$build/coverage.profdata"
fi

# Every instrumented executable of the build.
objects=()
while IFS= read -r binary; do
  objects+=(-object "$binary")
done < <(find "$build" -type f -perm -u+x ! -name '*.so' ! -path '*/CMakeFiles/*' -exec sh -c \
  'head -c 4 "$1" | grep -q ELF' _ {} \; -print | sort)

llvm-cov-14 export -summary-only -instr-profile="$build/coverage.profdata" "${objects[@]:1}" \
  "$root/geometry" "$root/graphs" "$root/algorithms" >"$build/coverage.json"

python3 - "$root" "$build/coverage.json" <<'EOF'
import json, sys, collections
root, path = sys.argv[1], sys.argv[2]
files = json.load(open(path))["data"][0]["files"]
folders = collections.defaultdict(lambda: [0, 0, 0, 0])
rows = []
for f in files:
    name = f["filename"][len(root) + 1:]
    s = f["summary"]
    lines, branches = s["lines"], s["branches"]
    folder = name.rsplit("/", 1)[0]
    for key in (folder.split("/")[0], folder) if "/" in folder else (folder,):
        acc = folders[key]
        acc[0] += lines["covered"]; acc[1] += lines["count"]
        acc[2] += branches["covered"]; acc[3] += branches["count"]
    if folder == "algorithms":
        rows.append((lines["percent"], name, lines, branches))
pct = lambda a, b: f"{100 * a / b:5.1f}%" if b else "    –"
print(f"{'folder':24} {'lines':>22} {'branches':>22}")
for key in sorted(folders):
    c, n, bc, bn = folders[key]
    print(f"{key:24} {pct(c, n)} ({c:6}/{n:6}) {pct(bc, bn)} ({bc:6}/{bn:6})")
print()
print(f"{'algorithms/ file':36} {'lines':>22} {'branches':>22}")
for _, name, lines, branches in sorted(rows):
    print(f"{name:36} {pct(lines['covered'], lines['count'])} ({lines['covered']:6}/{lines['count']:6})"
          f" {pct(branches['covered'], branches['count'])} ({branches['covered']:6}/{branches['count']:6})")
EOF
