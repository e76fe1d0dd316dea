"""meshstep.triangulate: the triangle package's dicts and switches."""
import re

import numpy as np
import pytest

import meshstep
from conftest import corpus_file, read_edge, read_ele, read_node
from mesh_checks import centroids, edge_uses, min_angles_deg, signed_areas

SQUARE = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
SQUARE_SEGMENTS = np.array([[0, 1], [1, 2], [2, 3], [3, 0]])


def box_with_hole():
    """A 3 x 3 box with a 1 x 1 square hole in its middle."""
    outer = [[0, 0], [3, 0], [3, 3], [0, 3]]
    inner = [[1, 1], [2, 1], [2, 2], [1, 2]]
    segments = [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4]]
    return dict(vertices=np.array(outer + inner, float), segments=np.array(segments), holes=np.array([[1.5, 1.5]]))


def test_guitar_pq30_is_the_command_lines_refine_min_angle_30(cli, tmp_path):
    poly = corpus_file("guitar.poly")
    cli("refine", poly, "--min-angle", "30", "-o", tmp_path / "guitar", "-q")
    first, xy, markers = read_node(tmp_path / "guitar.node")
    triangles = read_ele(tmp_path / "guitar.ele", first)

    t = meshstep.triangulate(meshstep.read_poly(poly), "pq30")
    assert t["vertices"].tolist() == [list(p) for p in xy]
    assert [tuple(r) for r in t["triangles"].tolist()] == triangles
    if markers is None:
        assert "vertex_markers" not in t
    else:
        assert t["vertex_markers"][:, 0].tolist() == markers
    assert min_angles_deg(t["vertices"], t["triangles"]).min() >= 30.0


def test_a_segment_to_a_missing_vertex_raises_value_error():
    with pytest.raises(ValueError, match="segments.*vertex 4"):
        meshstep.triangulate(dict(vertices=SQUARE, segments=[[0, 1], [3, 4]]), "p")
    with pytest.raises(ValueError, match="vertex -1"):
        meshstep.triangulate(dict(vertices=SQUARE, segments=[[0, -1]]), "p")


@pytest.mark.parametrize("opts,letter", [("pV", "V"), ("pqo2", "o"), ("pq30Yj", "j"), ("p?", "?")])
def test_an_unsupported_switch_raises_value_error_naming_it(opts, letter):
    with pytest.raises(ValueError, match=re.escape(f"switch '{letter}'")):
        meshstep.triangulate(dict(vertices=SQUARE), opts)


def test_square_with_quality_and_area_switches():
    # As the triangle package's first example: the square's corners, 'qa0.1'.
    t = meshstep.triangulate(dict(vertices=SQUARE), "qa0.1")
    areas = signed_areas(t["vertices"], t["triangles"])
    assert (areas > 0).all()
    assert areas.max() <= 0.1
    assert np.isclose(areas.sum(), 1.0)
    assert min_angles_deg(t["vertices"], t["triangles"]).min() >= 20.0
    assert len(t["triangles"]) > 10
    # No number after q: Triangle's 20 degrees; a smaller area: more triangles.
    finer = meshstep.triangulate(dict(vertices=SQUARE), "qa0.01")
    assert len(finer["triangles"]) > len(t["triangles"])
    assert signed_areas(finer["vertices"], finer["triangles"]).max() <= 0.01


def test_area_with_an_exponent_then_edges():
    t = meshstep.triangulate(dict(vertices=SQUARE, segments=SQUARE_SEGMENTS), "pa5e-3e")
    assert signed_areas(t["vertices"], t["triangles"]).max() <= 5e-3
    assert "edges" in t


def test_box_with_a_hole():
    t = meshstep.triangulate(box_with_hole(), "qpa0.05")
    v, tri = t["vertices"], t["triangles"]
    areas = signed_areas(v, tri)
    assert np.isclose(areas.sum(), 8.0)  # 9 less the hole's 1
    assert areas.max() <= 0.05
    c = centroids(v, tri)
    inside_hole = (c[:, 0] > 1) & (c[:, 0] < 2) & (c[:, 1] > 1) & (c[:, 1] < 2)
    assert not inside_hole.any()
    # Without p the segments and the hole are not used: the convex hull is meshed.
    plain = meshstep.triangulate(box_with_hole(), "")
    assert np.isclose(signed_areas(plain["vertices"], plain["triangles"]).sum(), 9.0)
    assert len(plain["segments"]) == 4  # the hull's edges only: the hole's square is not kept
    assert "holes" not in plain


def test_regions_with_attributes_pA():
    # Two halves of a rectangle split by a segment, a region point in each.
    v = np.array([[0, 0], [1, 0], [2, 0], [2, 1], [1, 1], [0, 1]], float)
    s = np.array([[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 0], [1, 4]])
    regions = np.array([[0.5, 0.5, 7.0, 0.0], [1.5, 0.5, 9.0, 0.0]])
    t = meshstep.triangulate(dict(vertices=v, segments=s, regions=regions), "pA")
    attributes = t["triangle_attributes"][:, 0]
    expected = np.where(centroids(t["vertices"], t["triangles"])[:, 0] < 1.0, 7.0, 9.0)
    assert attributes.tolist() == expected.tolist()
    # Without A the attributes are not returned, as with Triangle.
    assert "triangle_attributes" not in meshstep.triangulate(dict(vertices=v, segments=s, regions=regions), "p")


def test_regional_area_bounds_apply_with_a_alone():
    v = np.array([[0, 0], [1, 0], [2, 0], [2, 1], [1, 1], [0, 1]], float)
    s = np.array([[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 0], [1, 4]])
    regions = np.array([[0.5, 0.5, 1.0, 0.01], [1.5, 0.5, 2.0, 0.0]])
    t = meshstep.triangulate(dict(vertices=v, segments=s, regions=regions), "pa")
    c = centroids(t["vertices"], t["triangles"])
    areas = signed_areas(t["vertices"], t["triangles"])
    assert areas[c[:, 0] < 1].max() <= 0.01
    assert areas[c[:, 0] > 1].max() > 0.01  # the right half has no bound
    # Without 'a' the regions' areas are not bounds.
    coarse = meshstep.triangulate(dict(vertices=v, segments=s, regions=regions), "p")
    assert len(coarse["triangles"]) < len(t["triangles"])


def test_edges_are_the_command_lines_edge_file(cli, tmp_path):
    poly = corpus_file("guitar.poly")
    cli("triangulate", poly, "-e", "-o", tmp_path / "g", "-q")
    first, _, _ = read_node(tmp_path / "g.node")
    expected = read_edge(tmp_path / "g.edge", first)
    t = meshstep.triangulate(meshstep.read_poly(poly), "pe")
    got = list(zip(t["edges"][:, 0].tolist(), t["edges"][:, 1].tolist(), t["edge_markers"][:, 0].tolist()))
    assert got == expected


def test_neighbors_share_an_edge_opposite_each_corner():
    t = meshstep.triangulate(box_with_hole(), "pq25n")
    tri, nb = t["triangles"], t["neighbors"]
    uses = edge_uses(tri)
    for i, (row, neighbours) in enumerate(zip(tri, nb)):
        for k in range(3):
            a, b = row[(k + 1) % 3], row[(k + 2) % 3]
            if neighbours[k] == -1:
                assert uses[(min(a, b), max(a, b))] == 1
            else:
                assert {a, b} <= set(tri[neighbours[k]].tolist()) and neighbours[k] != i


def containing_triangle(vertices, triangles, point):
    """The index of a triangle containing point (closed), by barycentric signs."""
    a, b, c = (vertices[triangles[:, k]] for k in range(3))

    def cross(p, q, r):
        return (q[:, 0] - p[:, 0]) * (r[1] - p[:, 1]) - (q[:, 1] - p[:, 1]) * (r[0] - p[:, 0])

    inside = (cross(a, b, point) >= 0) & (cross(b, c, point) >= 0) & (cross(c, a, point) >= 0)
    return int(np.flatnonzero(inside)[0])


def test_refining_again_with_triangle_max_area_r_a():
    t = meshstep.triangulate(dict(vertices=SQUARE, segments=SQUARE_SEGMENTS), "pq")
    c = centroids(t["vertices"], t["triangles"])
    # Small triangles wanted in the old triangles on the left only.
    bounds = np.where(c[:, 0] < 0.5, 0.002, -1.0)
    t["triangle_max_area"] = bounds
    again = meshstep.triangulate(t, "ra")
    areas = signed_areas(again["vertices"], again["triangles"])
    assert len(again["triangles"]) > len(t["triangles"])
    assert np.isclose(areas.sum(), 1.0)
    for centroid, area in zip(centroids(again["vertices"], again["triangles"]), areas):
        bound = bounds[containing_triangle(t["vertices"], t["triangles"], centroid)]
        if bound > 0:
            assert area <= bound
    assert areas.max() > 0.002  # the right side had no bound
    # r without a: the areas are not bounds.
    assert len(meshstep.triangulate(t, "r")["triangles"]) < len(again["triangles"])


def test_conforming_delaunay_D_leaves_no_vertex_in_a_segments_diametral_circle():
    # A thin wedge: its long segments are encroached by the vertices opposite.
    v = np.array([[0, 0], [10, 0], [10, 1], [5, 0.3], [0, 1]], float)
    s = np.array([[0, 1], [1, 2], [2, 3], [3, 4], [4, 0]])
    t = meshstep.triangulate(dict(vertices=v, segments=s), "pDq10")
    pts = t["vertices"]
    for a, b in t["segments"]:
        middle = (pts[a] + pts[b]) / 2
        radius2 = np.sum((pts[a] - pts[b]) ** 2) / 4
        d2 = np.sum((pts - middle) ** 2, axis=1)
        d2[[a, b]] = np.inf
        assert d2.min() >= radius2 * (1 - 1e-12)


def test_convex_hull_c_keeps_the_hulls_triangles():
    v = np.array([[0, 0], [2, 0], [2, 2], [1, 0.5], [0, 2]], float)
    s = np.array([[0, 1], [1, 2], [2, 3], [3, 4], [4, 0]])
    inside = meshstep.triangulate(dict(vertices=v, segments=s), "p")
    hull = meshstep.triangulate(dict(vertices=v, segments=s), "pc")
    assert np.isclose(signed_areas(hull["vertices"], hull["triangles"]).sum(), 4.0)
    assert signed_areas(inside["vertices"], inside["triangles"]).sum() < 4.0 - 0.5


def test_steiner_cap_S():
    free = meshstep.triangulate(dict(vertices=SQUARE), "qa0.001")
    capped = meshstep.triangulate(dict(vertices=SQUARE), "qa0.001S10")
    assert len(capped["vertices"]) - 4 <= 10 < len(free["vertices"]) - 4
    none = meshstep.triangulate(dict(vertices=SQUARE), "qa0.001S")
    assert len(none["vertices"]) == 4


def test_angle_out_of_range_is_the_cores_message():
    with pytest.raises(ValueError, match="minimum angle 70 is out of range"):
        meshstep.triangulate(dict(vertices=SQUARE), "q70")


def test_switch_number_errors():
    with pytest.raises(ValueError, match="switch 'a'"):
        meshstep.triangulate(dict(vertices=SQUARE), "a1..2")
    with pytest.raises(ValueError, match="switch 'S'"):
        meshstep.triangulate(dict(vertices=SQUARE), "qS1.5")
    with pytest.raises(ValueError, match="switch 'S'"):
        meshstep.triangulate(dict(vertices=SQUARE), "qS.")


def test_delaunay_and_convex_hull_as_the_triangle_package_has_them():
    rng = np.random.default_rng(3)
    points = rng.random((200, 2))
    triangles = meshstep.delaunay(points)
    assert (signed_areas(points, triangles) > 0).all()
    # Empty circumcircles: no point strictly inside any triangle's circumcircle.
    a, b, c = (points[triangles[:, k]] for k in range(3))
    bx, by, cx, cy = b[:, 0] - a[:, 0], b[:, 1] - a[:, 1], c[:, 0] - a[:, 0], c[:, 1] - a[:, 1]
    d = 2 * (bx * cy - by * cx)
    ux = (cy * (bx ** 2 + by ** 2) - by * (cx ** 2 + cy ** 2)) / d
    uy = (bx * (cx ** 2 + cy ** 2) - cx * (bx ** 2 + by ** 2)) / d
    centers = a + np.column_stack([ux, uy])
    radius2 = ux ** 2 + uy ** 2
    for center, r2 in zip(centers, radius2):
        assert ((points - center) ** 2).sum(1).min() >= r2 * (1 - 1e-9)
    hull = meshstep.convex_hull(points)
    on_hull = set(hull.ravel().tolist())
    # Every point is left of (or on) every hull edge.
    for i, j in hull:
        e = points[j] - points[i]
        side = e[0] * (points[:, 1] - points[i, 1]) - e[1] * (points[:, 0] - points[i, 0])
        assert side.min() >= -1e-12
    assert len(hull) == len(on_hull)


def box_with_hole_and_wall():
    """box_with_hole, and an interior segment (a wall with triangles on both sides) below the hole."""
    box = box_with_hole()
    box["vertices"] = np.vstack([box["vertices"], [[0.5, 0.5], [2.5, 0.5]]])
    box["segments"] = np.vstack([box["segments"], [[8, 9]]])
    return box


def edge_set(pairs):
    return {tuple(sorted(map(int, e))) for e in pairs}


def boundary_edge_set(triangles):
    """Edges with a triangle on one side only, from the triangles alone."""
    return {e for e, n in edge_uses(triangles).items() if n == 1}


def test_y_keeps_the_boundary_segments_and_yy_every_segment():
    box = box_with_hole_and_wall()
    boundary = edge_set(box["segments"][:8])  # the outer square's and the hole's
    plain = meshstep.triangulate(box, "pq30")
    # Without Y the boundary is split (so what follows would fail without the switch).
    assert not boundary_edge_set(plain["triangles"]) <= boundary

    y = meshstep.triangulate(box, "pq30Y")
    assert boundary_edge_set(y["triangles"]) == boundary
    assert boundary <= edge_set(y["segments"])
    assert (8, 9) not in edge_set(y["segments"])  # the wall inside may be split
    assert len(y["vertices"]) > len(box["vertices"])

    yy = meshstep.triangulate(box, "pq30YY")
    assert edge_set(yy["segments"]) == edge_set(box["segments"])
    assert len(yy["segments"]) == len(box["segments"])
    assert boundary_edge_set(yy["triangles"]) == boundary
    # Three Y are two: nothing more to prohibit.
    assert edge_set(meshstep.triangulate(box, "pq30YYY")["segments"]) == edge_set(box["segments"])


def test_refine_split_segments_is_y_and_reports_what_it_left():
    box = box_with_hole_and_wall()
    t = meshstep.triangulate(box, "pq30YY")
    mesh = meshstep.refine(box["vertices"], box["segments"], box["holes"], min_angle=30, split_segments="none")
    assert mesh.vertices.tolist() == t["vertices"].tolist()
    assert mesh.triangles.tolist() == t["triangles"].tolist()
    assert mesh.stats["split_segments"] == "none"
    assert mesh.stats["segment_splits"] == 0
    below = int((min_angles_deg(mesh.vertices, mesh.triangles) < 30.0 - 1e-9).sum())
    assert mesh.stats["below_min_angle"] == below
    assert mesh.stats["bounds_met"] == (mesh.stats["bad_triangles"] == 0)
    with pytest.raises(ValueError, match="split-segments"):
        meshstep.refine(box["vertices"], box["segments"], split_segments="boundary")
