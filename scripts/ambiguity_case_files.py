"""Writes an ambiguity case (docs/ambiguity/NAME/) and measures it with `curvebench measure`.

A case is a point set S and two curves C1, C2 through it: points.xy, curve_K.svg (C_K as one SVG path,
one closed subpath per component), edges_K.edges (the ground truth: the polygon through S in C_K's
order), picture.svg, replay.sh and summary.json. The epsilons in summary.json are what `curvebench
measure` reads back from the written files, never the writer's own estimate; the test
certify.ambiguity_cases re-measures them. Shared by scripts/ambiguity_descent.py and
scripts/ambiguity_circle_chain.py.
"""
import json
import math
import os
import subprocess


def measure(curvebench, directory):
    """Epsilon of S on C1 and on C2, unfloored; inf where lfs vanishes (a cusp or a crossing)."""
    epsilons = []
    for k in (1, 2):
        out = subprocess.run([curvebench, "measure", "--curve", f"svg:{directory}/curve_{k}.svg", "-i",
                              f"{directory}/points.xy", "-e", f"{directory}/edges_{k}.edges", "--min-lfs", "0"],
                             capture_output=True, text=True, check=True).stdout
        epsilon = json.loads(out)["epsilon"]
        epsilons.append(math.inf if epsilon is None else epsilon)
    return epsilons


def write_case(directory, samples, paths, cycles, curvebench, record):
    """samples: (x, y) pairs; paths[K-1]: SVG path data of C_K; cycles[K-1]: C_K's cycles, each a list
    of sample indices in order along one component. Returns [epsilon(C1), epsilon(C2)]."""
    os.makedirs(directory, exist_ok=True)
    with open(f"{directory}/points.xy", "w") as f:
        f.writelines("%r %r\n" % (float(x), float(y)) for x, y in samples)
    for k in (1, 2):
        with open(f"{directory}/curve_{k}.svg", "w") as f:
            f.write('<svg xmlns="http://www.w3.org/2000/svg">\n'
                    f'<path fill="none" stroke="black" d="{paths[k - 1]}"/>\n</svg>\n')
        with open(f"{directory}/edges_{k}.edges", "w") as f:
            f.writelines(f"{cycle[i]} {cycle[(i + 1) % len(cycle)]}\n"
                         for cycle in cycles[k - 1] for i in range(len(cycle)))
    epsilons = measure(curvebench, directory)
    xs, ys = [float(p[0]) for p in samples], [float(p[1]) for p in samples]
    size = max(max(xs) - min(xs), max(ys) - min(ys))
    pad, w = 0.15 * size, 0.004 * size
    box = f"{min(xs) - pad} {-max(ys) - pad} {size + 2 * pad} {size + 2 * pad}"
    closest = min((math.hypot(xs[i] - xs[j], ys[i] - ys[j]) for i in range(len(xs)) for j in range(i)),
                  default=size)
    dot = min(2.5 * w, 0.2 * closest)  # dots never hide the arcs between close points
    dots = "".join(f'<circle cx="{x}" cy="{y}" r="{dot}"/>' for x, y in zip(xs, ys))
    with open(f"{directory}/picture.svg", "w") as f:
        f.write(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="{box}" width="800" height="800">'
                f'<title>ambiguous sampling: {len(samples)} points, epsilon {epsilons[0]!r} (C1, blue) and '
                f'{epsilons[1]!r} (C2, red dashed)</title><g transform="scale(1,-1)">'
                f'<path d="{paths[0]}" fill="none" stroke="#1f77b4" stroke-width="{w}"/>'
                f'<path d="{paths[1]}" fill="none" stroke="#d62728" stroke-width="{w}" '
                f'stroke-dasharray="{3 * w} {2 * w}"/>{dots}</g></svg>\n')
    with open(f"{directory}/summary.json", "w") as f:
        json.dump({"points": len(samples), "epsilon_1": epsilons[0], "epsilon_2": epsilons[1],
                   "max_epsilon": max(epsilons), **record}, f, indent=2)
        f.write("\n")
    with open(f"{directory}/replay.sh", "w") as f:
        f.write("#!/bin/sh\n# Re-measures S against C1 and C2 with the project's unfloored epsilon.\n"
                "cd \"$(dirname \"$0\")\"\n" + "".join(
                    f"${{CURVEBENCH:-curvebench}} measure --curve svg:curve_{k}.svg -i points.xy "
                    f"-e edges_{k}.edges --min-lfs 0\n" for k in (1, 2)))
    os.chmod(f"{directory}/replay.sh", 0o755)
    return epsilons
