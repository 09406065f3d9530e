#!/usr/bin/env python3
"""Fails when an #include runs back up the layers (DESIGN.md: data flows one way).

Usage: check_includes.py SOURCE_DIR

A folder may include itself and what it depends on, directly or through others, as the
table below says; it mirrors the libraries' target_link_libraries, so a new dependency is
a decision made here and in CMake together. tests/ and fuzz/ may include anything.
"""
import pathlib
import re
import sys

DEPENDS_ON = {
    "geometry": [],
    "geometry/io": ["geometry"],
    "geometry/curves": ["geometry/io"],
    "geometry/lfs": ["geometry/curves"],
    "geometry/sampling": ["geometry/lfs"],
    "geometry/image": ["geometry/sampling", "geometry/io"],
    "geometry/metrics": ["geometry"],
    "graphs": ["geometry"],
    "algorithms": ["graphs"],  # not geometry/io: algorithms read and write no files
    "certify": ["algorithms", "geometry/sampling"],
    "bench": ["certify", "geometry/image", "geometry/metrics"],
    "python": ["bench"],  # the bindings, over every layer; nothing includes them
}
INCLUDE = re.compile(r'^[ \t]*#[ \t]*include[ \t]+"([^"]+)"', re.MULTILINE)


def room(path):
    """The table's key for a file or include path: geometry/SUB, or the top-level folder."""
    parts = pathlib.PurePosixPath(path).parts
    if parts[0] == "geometry" and len(parts) > 2:
        return "geometry/" + parts[1]
    return parts[0]


def reachable(name, seen=None):
    seen = set() if seen is None else seen
    for dependency in DEPENDS_ON[name]:
        if dependency not in seen:
            seen.add(dependency)
            reachable(dependency, seen)
    return seen


def violations(source_dir):
    root = pathlib.Path(source_dir)
    tops = sorted({name.split("/")[0] for name in DEPENDS_ON})
    for path in sorted(file for top in tops for file in (root / top).rglob("*")):
        if path.suffix not in (".h", ".hpp", ".cpp", ".cc") or not path.is_file():
            continue
        relative = path.relative_to(root).as_posix()
        here = room(relative)
        if here not in DEPENDS_ON:
            continue  # tests/, fuzz/, cmake/, build trees
        allowed = reachable(here) | {here}
        text = path.read_text(encoding="utf-8", errors="replace")
        for match in INCLUDE.finditer(text):
            there = room(match.group(1))
            if there in DEPENDS_ON and there not in allowed:
                line = text.count("\n", 0, match.start()) + 1
                yield f"{relative}:{line}: {here} includes {match.group(1)} ({there} is not below it)"


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    found = list(violations(sys.argv[1]))
    for message in found:
        print(message)
    print(f"layering: {len(found)} include(s) running back up")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
