"""``refine``: meshstep's run description from Python, and the ``Mesh`` it returns."""
from __future__ import annotations

import os
import pathlib
from dataclasses import dataclass, field
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _meshstep

__all__ = ["Mesh", "refine", "algorithms"]

ArrayLike = Any  # anything numpy.asarray takes
PathLike = Union[str, "os.PathLike[str]"]


@dataclass
class Mesh:
    """A triangle mesh as numpy arrays, indices from 0.

    Attributes
    ----------
    vertices: (n, 2) float64. The input vertices first, in input order, then the Steiner
        vertices.
    triangles: (t, 3) int32, counterclockwise.
    segments: (s, 2) int32: the input segments' pieces (constrained edges).
    segment_markers: (s,) int32.
    markers: (n,) int32: each vertex's marker (input markers kept; a Steiner vertex gets the
        marker of the segment it split).
    attributes: (t, k) float64: each triangle's region attribute (k is 0 or 1).
    stats: the run's statistics, with the names and values of ``meshstep refine --stats json``
        (``ms`` holds the triangulation's and the refinement's milliseconds).
    """

    vertices: np.ndarray
    triangles: np.ndarray
    segments: np.ndarray
    segment_markers: np.ndarray
    markers: np.ndarray
    attributes: np.ndarray
    stats: Dict[str, Any] = field(default_factory=dict)

    def to_meshio(self):
        """The mesh as a ``meshio.Mesh`` (points with z = 0, one "triangle" cell block, the
        region attribute as cell data ``region`` when there is one)."""
        import meshio

        points = np.column_stack([self.vertices, np.zeros(len(self.vertices))])
        cell_data = {}
        if self.attributes.shape[1] > 0:
            cell_data["region"] = [self.attributes[:, 0].copy()]
        return meshio.Mesh(points, [("triangle", self.triangles.astype(np.int64))],
                           point_data={"marker": self.markers.copy()}, cell_data=cell_data)

    def __repr__(self) -> str:
        return (f"Mesh({len(self.vertices)} vertices, {len(self.triangles)} triangles, "
                f"{len(self.segments)} segments)")


def algorithms() -> List[str]:
    """The names ``refine(algorithm=...)`` accepts (``meshstep list`` describes them)."""
    return list(_meshstep.algorithms())


def _number(value: Any, name: str) -> str:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise TypeError(f"{name}: expected a number, got {value!r}")
    return repr(float(value)) if isinstance(value, (float, np.floating)) else str(int(value))


def _option_words(name: str, value: Any) -> List[str]:
    """``--NAME VALUE`` (or ``--NAME`` for a flag) as the command line writes it."""
    flag = "--" + name.replace("_", "-")
    if value is None or value is False:
        return []
    if value is True:
        return [flag]
    if isinstance(value, str):
        return [flag, value]
    if isinstance(value, os.PathLike):
        return [flag, os.fspath(value)]
    return [flag, _number(value, name)]


def _recipe_operations(recipe: Union[str, pathlib.Path]) -> Tuple[List[List[str]], List[str]]:
    if isinstance(recipe, pathlib.Path):
        origin, text = str(recipe), recipe.read_text()
    else:
        origin, text = "recipe", recipe
    operations, origins = [], []
    for number, line in enumerate(text.splitlines(), start=1):
        words = line.split("#", 1)[0].split()
        if words:
            operations.append(words)
            origins.append(f"{origin}:{number}: ")
    if not operations:
        raise ValueError(f"{origin}: no operation in the recipe (one 'refine ...' line at least)")
    return operations, origins


def refine(vertices: ArrayLike,
           segments: Optional[ArrayLike] = None,
           holes: Optional[ArrayLike] = None,
           regions: Optional[ArrayLike] = None,
           algorithm: str = "offcenter",
           min_angle: Optional[float] = None,
           max_area: Optional[float] = None,
           region: Union[None, Tuple[float, float, float, float], ArrayLike] = None,
           recipe: Union[None, str, pathlib.Path] = None,
           record: Optional[PathLike] = None,
           ds: str = "tds",
           *,
           segment_markers: Optional[ArrayLike] = None,
           vertex_markers: Optional[ArrayLike] = None,
           is_bad: Optional[Callable[[np.ndarray, float], bool]] = None,
           **options: Any) -> Mesh:
    """Triangulate a planar straight line graph and refine it into a quality mesh.

    Parameters
    ----------
    vertices: (n, 2) coordinates.
    segments: (m, 2) vertex indices (from 0) of the segments the mesh must keep; None: the
        convex hull of the points is meshed.
    holes: (h, 2) points inside holes; the triangles reachable from them are removed.
    regions: (r, 4) rows of x, y, attribute, maximum area (<= 0: none): the triangles
        reachable from (x, y) get the attribute, and the area bound.
    algorithm: one of ``algorithms()`` (``offcenter``, ``circumcenter``, ``lepp-centroid``, ...).
    min_angle: the smallest angle wanted, in degrees; max_area: the largest triangle area.
        With no bound at all, the algorithm's default applies (20.7 degrees for most).
    region: refine only there: a box ``(x0, y0, x1, y1)``, or an (k, 2) polygon.
    recipe: instead of the options, a recipe: its text (one ``refine --...`` operation a
        line, '#' comments) or a ``pathlib.Path`` to a recipe file; the operations run one
        after the other on the same mesh (docs/recipes.md).
    record: write every step of the run to this replay log (``meshstep log``, ``Log``).
    ds: the mesh data structure, ``tds`` or ``dcel`` (the same vertices and triangles either
        way; a triangle may be listed from another corner).
    segment_markers, vertex_markers: (m,) and (n,) integers carried to the output.
    is_bad: meshpy's ``refinement_func``: ``is_bad(vertices, area)`` gets a triangle's (3, 2)
        corners and its area and returns True to have it refined, besides the bounds.
    **options: any other option of ``meshstep refine``, with ``_`` for ``-``:
        ``max_angle=``, ``max_aspect=``, ``size=``, ``max_triangles=``, ``max_steiner=``,
        ``select=``, ``order=``, ``encroachment=``, ``insertion=``, ``convex_hull=True``,
        ``improve=True``, ``split_segments='interior'`` (never split a segment on the
        domain's boundary, Triangle's ``Y``) or ``'none'`` (no segment at all, ``YY``): the
        mesh is then constrained Delaunay, and ``stats['kept_segment_refusals']`` counts the
        bad triangles left because their point would encroach on a kept segment, ...

    Returns
    -------
    Mesh

    Raises
    ------
    ValueError: for an option or bound the command line would refuse (its message), arrays of
        the wrong shape, indices out of range, coordinates that are not finite, and every
        other input the core refuses.
    KeyboardInterrupt: on Ctrl+C; the run stops within about a second.

    Example
    -------
    >>> square = [[0, 0], [1, 0], [1, 1], [0, 1]]
    >>> mesh = refine(square, [[0, 1], [1, 2], [2, 3], [3, 0]], min_angle=30, max_area=0.01)
    >>> mesh.stats["bounds_met"]
    True
    """
    region_polygon = None
    words: List[str] = ["refine"]
    if recipe is not None:
        given = {"algorithm": algorithm != "offcenter", "min_angle": min_angle is not None,
                 "max_area": max_area is not None, "region": region is not None}
        clash = sorted([k for k, v in given.items() if v] + list(options))
        if clash:
            raise ValueError(f"recipe: its operations say the options; do not also give {', '.join(clash)}")
        operations, origins = _recipe_operations(recipe)
    else:
        words += ["--algorithm", algorithm]
        words += _option_words("min_angle", min_angle) + _option_words("max_area", max_area)
        if region is not None:
            if np.ndim(region) == 1 and len(region) == 4:  # four numbers: a box
                words += ["--region", ",".join(_number(v, "region") for v in region)]
            else:
                region_polygon = region
        for name, value in options.items():
            words += _option_words(name, value)
        operations, origins = [words], [""]
    result = _meshstep.refine(vertices, segments, segment_markers, holes, regions, vertex_markers,
                              operations, origins, ds, region_polygon,
                              "" if record is None else os.fspath(record), is_bad)
    markers = result["vertex_markers"]
    return Mesh(vertices=result["vertices"], triangles=result["triangles"], segments=result["segments"],
                segment_markers=result["segment_markers"][:, 0],
                markers=markers[:, 0] if len(markers) else np.zeros(len(result["vertices"]), np.int32),
                attributes=result["triangle_attributes"], stats=result["stats"])
