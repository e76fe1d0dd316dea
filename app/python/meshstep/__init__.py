"""meshstep: 2D Delaunay triangulation and quality refinement, with replayable runs.

Two ways in:

* ``triangulate(tri, opts)`` speaks the ``triangle`` package's language (its dict keys and
  Triangle's switch letters), so a script written for ``triangle`` runs after changing its
  import;
* ``refine(vertices, segments, ...)`` is the Pythonic front of meshstep's run description:
  an algorithm, its bounds, a region, a recipe, a replay log, and a ``Mesh`` of numpy arrays
  back;
* ``Log(path)`` reads a recorded run: its steps, the mesh after any step, its events, the
  explanation of each step, and pictures of any moment (``render``: RGB pixels through
  OpenGL; ``svg``: no GL needed).

Bad input raises ``ValueError`` with the core's message; long runs release the GIL and stop
with ``KeyboardInterrupt`` on Ctrl+C.
"""
from ._meshstep import __version__
from ._triangle import triangulate, delaunay, convex_hull, read_poly
from ._refine import Mesh, refine, algorithms
from ._log import GlUnavailable, Log, Picture, Svg, render
from ._terrain import terrain_tiles

__all__ = ["triangulate", "delaunay", "convex_hull", "read_poly", "refine", "Mesh", "algorithms", "Log", "Svg", "Picture", "GlUnavailable", "render", "terrain_tiles", "__version__"]
