#!/usr/bin/env python3
"""The layering check must fail on a back-include and pass on includes that run down."""
import pathlib
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).parent))
import check_includes  # noqa: E402


def found(files):
    with tempfile.TemporaryDirectory() as root:
        for name, text in files.items():
            path = pathlib.Path(root, name)
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text)
        return list(check_includes.violations(root))


cases = [
    ({"geometry/curves/a.h": '#include "geometry/sampling/sample.h"\n'}, 1),  # a room further down
    ({"geometry/io/a.cpp": '\n#include "geometry/curves/curve.h"\n'}, 1),
    ({"geometry/kernel.h": '#include "geometry/io/point_io.h"\n'}, 1),        # the root is below every room
    ({"algorithms/a.cpp": '#include "geometry/io/point_io.h"\n'}, 1),         # algorithms read no files
    ({"graphs/a.h": '#include "algorithms/registry.h"\n'}, 1),                # between layers
    ({"geometry/metrics/a.h": '#include "geometry/curves/curve.h"\n'}, 1),    # a sibling room, not below
    ({"bench/cli/a.cpp": '#include "geometry/image/binary_image.h"\n#include "bench/runner/run.h"\n'}, 0),
    ({"geometry/image/a.cpp": '#include "geometry/curves/curve.h"\n'}, 0),    # through sampling and lfs
    ({"algorithms/a.cpp": '#include "graphs/graph.h"\n#include "geometry/kernel.h"\n#include <vector>\n'}, 0),
    ({"tests/a.cpp": '#include "bench/runner/run.h"\n'}, 0),
]
failures = 0
for files, expected in cases:
    got = found(files)
    if len(got) != expected:
        failures += 1
        print(f"FAILED: {files} gave {got}, expected {expected} finding(s)")
message = found({"geometry/io/a.cpp": '\n\n#include "geometry/curves/curve.h"\n'})
if not message or not message[0].startswith("geometry/io/a.cpp:3: "):
    failures += 1
    print(f"FAILED: the message names the file and line: {message}")
print(f"{len(cases) + 1 - failures} passed, {failures} failed")
sys.exit(1 if failures else 0)
