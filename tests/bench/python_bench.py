#!/usr/bin/env python3
"""The Python module against the command line, on the same work (docs/python.md).

1. Delaunay triangulation of N random points (numpy, seed 1): meshstep.triangulate(dict(
   vertices=P)) timed round the call, from the numpy array in to the numpy arrays out,
   against `meshstep triangulate P.node --stats json --no-output -q`'s own time
   (ms.triangulate: the triangulation and its conversion to arrays, no file reading).
2. Refinement of A.poly at 30 degrees, max area 7.7e-8 (about 1.3M triangles):
   meshstep.refine(...) round the call against `meshstep refine A.poly ... --stats json`'s
   ms.triangulate + ms.refine.

Runs alternate (Python, command line, then command line, Python, ...) so that drift in the
machine's speed falls on both; medians are reported, with each ratio Python / command line.

Usage: PYTHONPATH=build/python /usr/bin/python3 tests/bench/python_bench.py \\
           --meshstep build/app/meshstep --poly ../shared/data/pslg/A.poly [--points 1e6] [--repeat 5]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import meshstep


def cli_stats(binary, *args):
    out = subprocess.run([binary, *args, "--stats", "json", "--no-output", "-q"], check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out.strip().splitlines()[-1])


def write_node(path, points):
    with open(path, "w") as f:
        f.write(f"{len(points)} 2 0 0\n")
        for i, (x, y) in enumerate(points.tolist()):
            f.write(f"{i} {x!r} {y!r}\n")


def alternate(repeat, python_run, cli_run):
    py, cli = [], []
    for i in range(repeat):
        order = [(python_run, py), (cli_run, cli)]
        for run, into in (order if i % 2 == 0 else order[::-1]):
            into.append(run())
    return py, cli


def report(name, py, cli):
    p, c = statistics.median(py), statistics.median(cli)
    print(f"{name}: python {p:.1f} ms (runs {', '.join(f'{v:.0f}' for v in py)}), "
          f"command line {c:.1f} ms (runs {', '.join(f'{v:.0f}' for v in cli)}): ratio {p / c:.3f}")
    return {"name": name, "python_ms": p, "cli_ms": c, "ratio": p / c}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--meshstep", required=True, help="the meshstep program")
    parser.add_argument("--poly", help="A.poly (the refinement is skipped without it)")
    parser.add_argument("--points", type=float, default=1e6)
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    if not os.access(args.meshstep, os.X_OK):
        parser.error(f"--meshstep {args.meshstep}: not an executable")
    results = []
    with tempfile.TemporaryDirectory() as tmp:
        points = np.random.default_rng(1).random((int(args.points), 2))
        node = os.path.join(tmp, "points.node")
        write_node(node, points)

        def python_triangulate():
            start = time.perf_counter()
            t = meshstep.triangulate(dict(vertices=points), "")
            elapsed = (time.perf_counter() - start) * 1e3
            assert len(t["triangles"]) > len(points)
            return elapsed

        def cli_triangulate():
            return cli_stats(args.meshstep, "triangulate", node)["ms"]["triangulate"]

        results.append(report(f"triangulate {len(points)} points", *alternate(args.repeat, python_triangulate,
                                                                               cli_triangulate)))
    if args.poly:
        d = meshstep.read_poly(args.poly)
        bounds = dict(min_angle=30, max_area=7.7e-8)

        def python_refine():
            start = time.perf_counter()
            m = meshstep.refine(d["vertices"], d.get("segments"), d.get("holes"), d.get("regions"),
                                segment_markers=d.get("segment_markers"), **bounds)
            elapsed = (time.perf_counter() - start) * 1e3
            python_refine.triangles = len(m.triangles)
            return elapsed

        def cli_refine():
            s = cli_stats(args.meshstep, "refine", args.poly, "--min-angle", "30", "--max-area", "7.7e-8")
            cli_refine.triangles = s["triangles"]
            return s["ms"]["triangulate"] + s["ms"]["refine"]

        r = report("refine A.poly at 30 degrees, max area 7.7e-8",
                   *alternate(args.repeat, python_refine, cli_refine))
        if python_refine.triangles != cli_refine.triangles:
            print(f"error: python made {python_refine.triangles} triangles, the command line {cli_refine.triangles}")
            return 1
        results.append(r)
    print(json.dumps(results))
    return 0


if __name__ == "__main__":
    sys.exit(main())
