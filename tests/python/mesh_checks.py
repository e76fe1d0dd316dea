"""Geometric checks of a mesh, in numpy, independent of meshstep's own checker."""
import numpy as np


def signed_areas(vertices, triangles):
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    return 0.5 * ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))


def min_angles_deg(vertices, triangles):
    """Each triangle's smallest angle."""
    p = [vertices[triangles[:, k]] for k in range(3)]
    angles = []
    for k in range(3):
        u = p[(k + 1) % 3] - p[k]
        v = p[(k + 2) % 3] - p[k]
        cos = np.einsum("ij,ij->i", u, v) / (np.linalg.norm(u, axis=1) * np.linalg.norm(v, axis=1))
        angles.append(np.degrees(np.arccos(np.clip(cos, -1, 1))))
    return np.min(angles, axis=0)


def centroids(vertices, triangles):
    return vertices[triangles].mean(axis=1)


def edge_uses(triangles):
    """How many triangles use each undirected edge: {(min, max): count}."""
    uses = {}
    for t in triangles:
        for k in range(3):
            a, b = int(t[(k + 1) % 3]), int(t[(k + 2) % 3])
            key = (min(a, b), max(a, b))
            uses[key] = uses.get(key, 0) + 1
    return uses
