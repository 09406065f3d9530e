#!/usr/bin/env bash
# curvebench as a package, from a copy of examples/ outside the tree.
#
#   package_test.sh installed_example BUILD SOURCE
#     cmake --install BUILD into a temporary prefix; examples/in-process built against it
#     with find_package(curvebench) and curvebench_add_program; its program runs
#     `run smoke`, `certify --count 50`, `hunt --seconds 10`, its benchmark and its fuzz
#     target; its rows equal those of the same algorithm behind `exec:`, runtimes aside.
#   package_test.sh deb BUILD SOURCE
#     cpack -G DEB; the package unpacked with dpkg-deb -x; its `curvebench list` runs, its
#     Python module (when built) imports, and the example configures and builds against
#     the unpacked tree.
set -uo pipefail
mode="$1" build="$2" source="$3"
python=/usr/bin/python3
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
source "$source/tests/support/check.sh"
cp -r "$source/examples" "$work/examples"
cd "$work"  # nothing below may find data/ by the working directory

# Builds examples/in-process against PREFIX into DIR (targets: the rest of the arguments).
build_example() {
  local prefix="$1" dir="$2"; shift 2
  local targets=()
  (($# > 0)) && targets=(--target "$@")
  cmake -S "$work/examples/in-process" -B "$dir" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" >"$dir.log" 2>&1 &&
    cmake --build "$dir" -j"$(nproc)" "${targets[@]}" >>"$dir.log" 2>&1 || { cat "$dir.log"; return 1; }
}

# Neither the build tree nor the source tree may appear in what the example was built with.
built_from_package_only() {
  ! grep -rlF -e "$build" -e "$source" "$1/build.ninja" "$1/CMakeCache.txt"
}

if [[ $mode == installed_example ]]; then
  prefix="$work/prefix"
  check "cmake --install puts the command, libraries, headers and package config in a prefix" sh -c "
    cmake --install '$build' --prefix '$prefix' >'$work/install.log' 2>&1 || { cat '$work/install.log'; exit 1; }
    test -x '$prefix/bin/curvebench' && test -f '$prefix/lib/cmake/curvebench/curvebenchConfig.cmake' &&
    test -f '$prefix/lib/cmake/curvebench/curvebenchConfigVersion.cmake' &&
    test -f '$prefix/include/curvebench/algorithms/registry.h' && test -f '$prefix/include/curvebench/bench/cli/program.h' &&
    test ! -e '$prefix/include/curvebench/bench/cli/run_command.h' && test -d '$prefix/share/curvebench/data/svg' &&
    ls '$prefix'/lib/libcurvebench_*.a >/dev/null"
  check "the example builds against the prefix: my-curvebench, its benchmark and its fuzz target" \
    build_example "$prefix" "$work/example"
  check "and against the package alone, not the build or source tree" built_from_package_only "$work/example"
  program="$work/example/my-curvebench"
  check "my-curvebench reads the data and report scripts installed in the prefix" sh -c "
    '$program' list data | grep -qxF 'data: $prefix/share/curvebench/data'"

  check "my-curvebench lists the registered algorithm beside the built-ins" sh -c "
    '$program' list algorithms | grep -q '^naive-nn-crust ' && '$program' list algorithms | grep -q '^hnn-crust '"
  check "run smoke: the registered algorithm and a built-in in one run and one report" sh -c "
    '$program' run smoke -a naive-nn-crust -a nn-crust -q -o '$work/smoke' >/dev/null &&
    test -s '$work/smoke/report.html' && test \$(grep -c ',naive-nn-crust,' '$work/smoke/results.csv') -eq 2"

  # The same algorithm behind exec: (examples/cpp, the program of ../algorithms.json).
  cmake -S "$work/examples/cpp" -B "$work/examples/cpp/build" >"$work/exec.log" 2>&1 &&
    cmake --build "$work/examples/cpp/build" >>"$work/exec.log" 2>&1 || cat "$work/exec.log"
  for suite in smoke sampling; do
    "$program" run "$suite" -a naive-nn-crust -q --no-report --pictures none -o "$work/in-process-$suite" >/dev/null
    "$prefix/bin/curvebench" run "$suite" --algorithm-file "$work/examples/algorithms.json" -a naive-nn-crust-cpp -q \
      --no-report --pictures none -o "$work/exec-$suite" >/dev/null
    check "$suite: the in-process rows equal the exec: rows, runtimes aside" "$python" -c '
import csv, sys
def rows(path):
    out = []
    for r in csv.DictReader(open(path)):
        for column in ("algorithm", "runtime_ms", "startup_ms", "picture"):
            r.pop(column)
        out.append(r)
    return out
a, b = rows(sys.argv[1]), rows(sys.argv[2])
print(f"    {len(a)} rows in-process, {len(b)} behind exec:")
sys.exit(0 if a and a == b and all(r["status"] == "ok" for r in a) else 1)' \
      "$work/in-process-$suite/results.csv" "$work/exec-$suite/results.csv"
  done

  check "certify --count 50: NN-Crust's theorem holds for the registered algorithm on all 50 cases" sh -c "
    '$program' certify -a naive-nn-crust --count 50 --json -q -o '$work/certify' >'$work/certify.json' &&
    '$python' -c '
import json, sys
s = json.load(open(sys.argv[1]))
print(\"    \", {k: s[k] for k in (\"cases\", \"passed\", \"failures\", \"inconclusive\")})
sys.exit(0 if s[\"cases\"] == 50 and s[\"passed\"] + s[\"inconclusive\"] == 50 and s[\"failures\"] == 0 else 1)' '$work/certify.json'"
  check "hunt --seconds 10 runs the registered algorithm in-process" sh -c "
    '$program' hunt -a naive-nn-crust --seconds 10 --json -o '$work/hunt' >'$work/hunt.json' &&
    '$python' -c '
import json, os, sys
h = json.load(open(sys.argv[1]))
sys.exit(0 if h[\"cases\"] > 0 and all(os.path.exists(f[\"replay\"]) for f in h[\"findings\"]) else 1)' '$work/hunt.json'"
  check "the benchmark times it over growing n with a complexity fit" sh -c "
    '$work/example/my-curvebench-benchmark' --benchmark_filter='naive-nn-crust/1000\$' --benchmark_min_time=0 \
      >'$work/benchmark.txt' 2>&1 && grep -q '^naive-nn-crust/1000 ' '$work/benchmark.txt' || { cat '$work/benchmark.txt'; exit 1; }"
  check "the fuzz target (clang, ASan, UBSan) runs 5 s without a finding" sh -c "
    cd '$work' && '$work/example/my-curvebench-fuzz' -max_total_time=5 -timeout=10 >'$work/fuzz.log' 2>&1 &&
    grep -q '^Done [0-9]* runs' '$work/fuzz.log' || { tail -n 30 '$work/fuzz.log'; exit 1; }"
  finish
fi

if [[ $mode == deb ]]; then
  check "cpack -G DEB builds the package" sh -c "
    cd '$build' && cpack -G DEB -B '$work/cpack' >'$work/cpack.log' 2>&1 || { cat '$work/cpack.log'; exit 1; }"
  deb=$(find "$work/cpack" -maxdepth 1 -name 'curvebench_*.deb' | head -n 1)
  check "its Depends names the Debian packages a library user compiles against" sh -c "
    dpkg-deb -f '$deb' Depends | tr ',' '\n' | sed 's/ //g' | sort >'$work/depends' &&
    for p in libcgal-dev libboost-graph-dev libtbb-dev libfreetype-dev libcli11-dev nlohmann-json3-dev; do
      grep -qx \$p '$work/depends' || exit 1; done"
  root="$work/root"
  check "dpkg-deb -x unpacks it (not installed into the system)" dpkg-deb -x "$deb" "$root"
  check "the unpacked curvebench list runs" sh -c "'$root/usr/bin/curvebench' list algorithms | grep -q '^hnn-crust '"
  check "the unpacked curvebench reads its own bundled data and report scripts" sh -c "
    '$root/usr/bin/curvebench' list data | grep -qxF 'data: $root/usr/share/curvebench/data' &&
    '$root/usr/bin/curvebench' run smoke -a nn-crust -q -o '$work/smoke' >/dev/null && test -s '$work/smoke/report.html'"
  if ls "$build"/python/curvebench/_curvebench*.so >/dev/null 2>&1; then  # the Python module was built
    check "its Python module imports from the unpacked /usr/lib/python3/dist-packages, with the package's data" \
      env -u CURVEBENCH_ROOT PYTHONPATH="$root/usr/lib/python3/dist-packages" "$python" -c "
import os, curvebench
assert curvebench.__file__.startswith('$root/usr/lib/python3/dist-packages/'), curvebench.__file__
assert os.path.realpath(curvebench._core.resource_root()) == os.path.realpath('$root/usr/share/curvebench')
assert (curvebench.run('smoke', ['nn-crust']).results.status == 'ok').all()"
    check "its Depends names python3-numpy" sh -c "dpkg-deb -f '$deb' Depends | grep -q python3-numpy"
  fi
  check "the example configures and builds against the unpacked tree" build_example "$root/usr" "$work/example" my-curvebench
  check "and against the package alone" built_from_package_only "$work/example"
  check "its program lists the registered algorithm" sh -c "'$work/example/my-curvebench' list algorithms | grep -q '^naive-nn-crust '"
  finish
fi
echo "usage: $0 installed_example|deb BUILD SOURCE" >&2
exit 2
