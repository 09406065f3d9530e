#!/usr/bin/env bash
# The Python module as the package installs it: `cmake --install BUILD` into a temporary
# prefix, then `import curvebench` from LIBDIR/python3/dist-packages there (not from the
# build tree), reading the prefix's own share/curvebench.
#
#   installed_test.sh BUILD PYTHON
set -uo pipefail
build="$1" python="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
source "$(dirname "${BASH_SOURCE[0]}")/../support/check.sh"
prefix="$work/prefix"

check "cmake --install puts the package under lib/python3/dist-packages" sh -c "
  cmake --install '$build' --prefix '$prefix' >'$work/install.log' 2>&1 || { cat '$work/install.log'; exit 1; }
  ls '$prefix'/lib*/python3/dist-packages/curvebench/_curvebench*.so >/dev/null &&
  test -f '$prefix'/lib*/python3/dist-packages/curvebench/__init__.pyi"
site=$(dirname "$(ls -d "$prefix"/lib*/python3/dist-packages/curvebench)")
cd "$work"  # nothing may come from the source or build tree by the working directory
check "python3 -c 'import curvebench' from the prefix, with its own data" \
  env -u CURVEBENCH_ROOT PYTHONPATH="$site" "$python" -c "
import curvebench, os, sys
assert curvebench.__file__.startswith('$site'), curvebench.__file__
root = os.path.realpath(curvebench._core.resource_root())
assert root == os.path.realpath('$prefix/share/curvebench'), root
s = curvebench.sample('svg:' + os.path.join(root, 'data/svg/simple.svg'), epsilon=0.3, safe=True)
r = curvebench.reconstruct(s.points, 'nn-crust')
assert curvebench.evaluate(s.points, r.edges, s.edges)['exact']
frame = curvebench.run('smoke', ['nn-crust', lambda p: curvebench.reconstruct(p, 'crust').edges]).results
assert (frame.status == 'ok').all() and frame.exact.all(), frame
print('   ', len(s), 'points of simple.svg from', root, '; run smoke:', len(frame), 'jobs ok')"
finish
