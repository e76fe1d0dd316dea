#!/usr/bin/python3
"""Reads back every 2D mesh format meshstep writes with independent readers and compares
the triangles with Triangle's files (.node/.ele/.poly) written by the same run.

meshio (Debian's python3-meshio) reads .msh, .vtu, .obj, .off, .ply and .stl; when gmsh is
installed, gmsh itself also reads the .msh and saves it again as MSH 2.2, which meshio reads
back. Exit status 77 (CTest's SKIP_RETURN_CODE) when meshio is missing.

usage: check_with_meshio.py MESHSTEP ASSETS_FOLDER
"""
import math
import os
import shutil
import subprocess
import sys
import tempfile

SKIP = 77

try:
    import meshio
    import numpy as np
except ImportError as e:  # the test says so, and CTest counts it as skipped
    print(f"SKIP: meshio or numpy is not installed ({e}); apt-get install python3-meshio")
    sys.exit(SKIP)


def rows(path):
    """The non-comment lines of one of Triangle's files, as lists of words."""
    out = []
    with open(path) as f:
        for line in f:
            words = line.split("#", 1)[0].split()
            if words:
                out.append(words)
    return out


def read_triangle_files(prefix):
    node = rows(prefix + ".node")
    n, dim, attrs, markers = (int(w) for w in node[0])
    first = int(node[1][0])
    points = np.array([[float(r[1]), float(r[2])] for r in node[1:1 + n]])
    ele = rows(prefix + ".ele")
    t, corners, tattrs = (int(w) for w in ele[0])
    triangles = np.array([[int(r[1]) - first, int(r[2]) - first, int(r[3]) - first] for r in ele[1:1 + t]])
    regions = np.array([float(r[4]) for r in ele[1:1 + t]]) if tattrs else np.zeros(t)
    poly = rows(prefix + ".poly")
    segments = int(poly[1][0])
    seg_markers = sorted({int(r[3]) for r in poly[2:2 + segments]}) if int(poly[1][1]) else []
    return points, triangles, regions, segments, seg_markers


def canonical(points, triangles, as_float32=False, digits=None):
    """Each triangle as its corners' coordinates, rotated to start at the smallest corner
    (orientation kept): a set that any renumbering of the vertices leaves equal. float32:
    as binary STL stores them; digits: rounded to that many significant digits (gmsh
    writes 16, one short of a double's round trip)."""
    def coordinate(c):
        c = float(np.float32(c)) if as_float32 else float(c)
        return float(f"{c:.{digits}g}") if digits else c
    out = set()
    for t in triangles:
        corners = [tuple(coordinate(c) for c in points[v][:2]) for v in t]
        k = corners.index(min(corners))
        out.add(tuple(corners[k:] + corners[:k]))
    return out


def min_angle(a, b, c):
    def angle(p, q, r):
        u, v = q - p, r - p
        return math.degrees(math.atan2(abs(u[0] * v[1] - u[1] * v[0]), u[0] * v[0] + u[1] * v[1]))
    return min(angle(a, b, c), angle(b, c, a), angle(c, a, b))


def check(name, cond, failures):
    print(("ok   " if cond else "FAIL ") + name)
    if not cond:
        failures.append(name)


def main():
    meshstep, assets = sys.argv[1], sys.argv[2]
    failures = []
    work = tempfile.mkdtemp(prefix="meshstep_formats_")
    try:
        lake = os.path.join(work, "lake.geojson")
        with open(lake, "w") as f:
            f.write('{"type": "Polygon", "coordinates": ['
                    '[[0,0],[4,0],[4,4],[0,4],[0,0]],'
                    '[[1,1],[3,1],[3,1.5],[1.5,1.5],[1.5,2.5],[3,2.5],[3,3],[1,3],[1,1]]]}')
        inputs = [(os.path.join(assets, "examples", "plate.poly"), ["--min-angle", "28"]),
                  (lake, ["--min-angle", "28", "--max-area", "0.05"])]
        for source, options in inputs:
            label = os.path.basename(source)
            base = os.path.join(work, label + ".base")
            subprocess.run([meshstep, "refine", source, *options, "-q", "-o", base], check=True)
            points, triangles, regions, segments, seg_markers = read_triangle_files(base)
            expected = canonical(points, triangles)
            for ext in (".msh", ".vtu", ".obj", ".off", ".ply", ".stl"):
                out = os.path.join(work, label + ext)
                subprocess.run([meshstep, "refine", source, *options, "-q", "-o", out], check=True)
                m = meshio.read(out)
                got = m.cells_dict.get("triangle", np.zeros((0, 3), dtype=int))
                check(f"{label}{ext}: meshio reads {len(got)} triangles, the .ele has {len(triangles)}",
                      len(got) == len(triangles), failures)
                check(f"{label}{ext}: the same triangles (by their corners)",
                      canonical(m.points, got) == canonical(points, triangles, as_float32=ext == ".stl"), failures)
                if ext == ".msh":
                    lines = m.cells_dict.get("line", np.zeros((0, 2)))
                    check(f"{label}.msh: {len(lines)} line elements for the .poly's {segments} segments",
                          len(lines) == segments, failures)
                    names = {name for name in m.field_data}
                    wanted = {f"marker {k}" for k in seg_markers}
                    check(f"{label}.msh: physical groups {sorted(names)} name the markers {sorted(wanted)}",
                          wanted <= names, failures)
                if ext == ".vtu":
                    region = m.cell_data_dict["region"]["triangle"]
                    check(f"{label}.vtu: region data as the .ele's attributes",
                          np.array_equal(region, regions), failures)
                    angles = m.cell_data_dict["min_angle"]["triangle"]
                    mine = np.array([min_angle(*points[t]) for t in triangles])
                    check(f"{label}.vtu: min_angle within 1e-9 degrees of this script's",
                          np.allclose(angles, mine, rtol=0, atol=1e-9), failures)
                    quality = m.cell_data_dict["quality"]["triangle"]
                    check(f"{label}.vtu: quality = min_angle / 60", np.allclose(quality, mine / 60, atol=1e-11), failures)
            gmsh = shutil.which("gmsh")
            if not gmsh:
                print("SKIP (part): gmsh is not installed; the .msh was read by meshio only")
                continue
            again = os.path.join(work, label + ".gmsh22.msh")
            subprocess.run([gmsh, os.path.join(work, label + ".msh"), "-save", "-format", "msh22", "-o", again,
                            "-v", "1"], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            m = meshio.read(again)
            got = m.cells_dict.get("triangle", np.zeros((0, 3), dtype=int))
            # gmsh keeps the node tags (1..N, the .node's order) and writes 16 digits, one
            # short of a double's round trip: the same triangles by their vertex numbers, at
            # coordinates within a rounding of the .node's.
            def by_index(tris):
                return {tuple(np.roll(t, -int(np.argmin(t)))) for t in np.asarray(tris, dtype=np.int64)}
            check(f"{label}.msh through gmsh: {len(got)} triangles, the same vertex numbers",
                  by_index(got) == by_index(triangles), failures)
            check(f"{label}.msh through gmsh: the same coordinates to 1e-15",
                  m.points.shape[0] == len(points) and np.allclose(m.points[:, :2], points, rtol=1e-15, atol=0),
                  failures)
            lines = m.cells_dict.get("line", np.zeros((0, 2)))
            check(f"{label}.msh through gmsh: {len(lines)} line elements for {segments} segments",
                  len(lines) == segments, failures)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    if failures:
        print(f"{len(failures)} checks failed")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
