#!/usr/bin/env bash
# Installs the Debian packages curvebench needs, and only those that are missing.
#   scripts/setup.sh        everything: the build, the tests, benchmarks, fuzzers, the browser check,
#                           Slurm for the cluster test
#   scripts/setup.sh run    only what `curvebench` and its report need (scripts/run.sh)
# Safe to run repeatedly; it calls apt-get only when something is absent.
set -euo pipefail

run_packages=(
  build-essential cmake ninja-build
  libcgal-dev libgmp-dev libmpfr-dev
  libboost-graph-dev
  libfreetype-dev fonts-dejavu-core
  libtbb-dev libcli11-dev nlohmann-json3-dev librapidcheck-dev
  python3-matplotlib
)
test_packages=(
  libbenchmark-dev libgtest-dev
  clang-14 libclang-rt-14-dev
  chromium chromium-driver python3-selenium
  python3-scipy
  # the Python module (python/, docs/python.md) and its tests
  python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pandas python3-pytest python3-hypothesis
  doxygen  # the API reference (`docs` target), which the ctest api_reference builds
  slurm-wlm munge  # tests/cli/curvebench_slurm_test.sh starts a one-node Slurm cluster of its own
)
case "${1:-test}" in
  run) packages=("${run_packages[@]}") ;;
  test) packages=("${run_packages[@]}" "${test_packages[@]}") ;;
  *) echo "usage: $0 [run|test]" >&2; exit 2 ;;
esac

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  [[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
