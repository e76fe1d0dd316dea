"""The ``triangle`` package's call: ``triangulate(tri, opts)``."""
from __future__ import annotations

import os
from typing import Any, Dict, Mapping, Union

import numpy as np

from . import _meshstep

__all__ = ["triangulate", "delaunay", "convex_hull", "read_poly"]


def triangulate(tri: Mapping[str, Any], opts: str = "") -> Dict[str, np.ndarray]:
    """Triangulate or refine a planar straight line graph given as the ``triangle`` package does.

    Parameters
    ----------
    tri:
        A dict of arrays, indices from 0: ``vertices`` (n, 2), and optionally
        ``vertex_markers`` (n,) or (n, 1), ``vertex_attributes`` (n, k), ``segments`` (m, 2),
        ``segment_markers``, ``holes`` (h, 2), ``regions`` (r, 4: x, y, attribute, max area),
        and with ``r`` also ``triangles`` (t, 3) and ``triangle_max_area``.
    opts:
        Triangle's switches: ``p`` (use the segments, holes and regions), ``q[ANGLE]``
        (minimum angle, 20 degrees when no number follows), ``a[AREA]`` (maximum area) and
        ``a`` alone (the regions' areas, or with ``r`` the triangles' ``triangle_max_area``),
        ``c`` (keep the convex hull), ``r`` (refine ``tri['triangles']`` again), ``e`` (output
        edges), ``n`` (output neighbours), ``D`` (conforming Delaunay: encroachment by
        diametral circles), ``Y`` (no Steiner vertex on the boundary's segments: they stay as
        given, the mesh is constrained Delaunay, and triangles near them may miss the bounds),
        ``YY`` (none on any segment), ``S[N]`` (at most N Steiner vertices; ``S`` or ``S0``: none),
        ``A`` (output each triangle's region attribute). ``z`` and ``Q`` are accepted and
        change nothing. Any other letter raises ``ValueError`` naming it.

    Returns
    -------
    dict
        ``vertices``, ``vertex_markers`` (when the mesh has markers), ``vertex_attributes``,
        ``triangles``, ``segments`` and ``segment_markers``, ``holes``, ``regions``, and as
        asked ``triangle_attributes`` (A), ``edges`` and ``edge_markers`` (e), ``neighbors``
        (n; -1 where there is none). Markers and attributes are (n, 1) columns.

    The refinement is meshstep's off-center refinement (``meshstep refine``'s default), so
    ``triangulate(tri, 'pq30')`` is the mesh of ``meshstep refine IN.poly --min-angle 30``.

    Raises
    ------
    ValueError
        For a switch not supported, a bound out of range, an array of the wrong shape, a
        segment naming a missing vertex, coordinates that are not finite, and every other
        input the core refuses (with the core's message).
    """
    if not isinstance(opts, str):
        raise TypeError(f"opts: expected a str of switches such as 'pq30', got {type(opts).__name__}")
    return _meshstep.triangulate(dict(tri), opts)


def read_poly(path: Union[str, "os.PathLike[str]"]) -> Dict[str, np.ndarray]:
    """A ``.poly`` or ``.node`` file (Triangle's formats) as ``triangulate``'s input dict.

    Indices start at 0 whatever the file's numbering. Raises ``ValueError`` with
    ``FILE:LINE: what is wrong`` for a malformed file.
    """
    return _meshstep.read_poly(os.fspath(path))


def delaunay(pts: Any) -> np.ndarray:
    """The Delaunay triangulation of (n, 2) points, as the triangle package's ``delaunay``:
    (t, 3) vertex indices, counterclockwise. Duplicate points are used once."""
    return triangulate({"vertices": pts}, "")["triangles"]


def convex_hull(pts: Any) -> np.ndarray:
    """The convex hull of (n, 2) points, as the triangle package's ``convex_hull``: its edges,
    (h, 2) vertex indices, each directed counterclockwise (the points on its left)."""
    points = np.asarray(pts, dtype=float)
    t = triangulate({"vertices": points}, "")
    edges = t["segments"].copy()
    # Direct each edge so that a point inside (the centroid of the hull's corners) is on its left.
    inside = points[np.unique(edges)].mean(axis=0)
    a, b = points[edges[:, 0]], points[edges[:, 1]]
    left = (b[:, 0] - a[:, 0]) * (inside[1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (inside[0] - a[:, 0])
    edges[left < 0] = edges[left < 0][:, ::-1]
    return edges
