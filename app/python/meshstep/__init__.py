"""meshstep: 2D Delaunay triangulation and refinement (placeholder)."""
from ._meshstep import triangulate, read_poly, __version__
