"""meshstep.refine: the run description from Python, and the Mesh it returns."""
import json
import pathlib

import numpy as np
import pytest

import meshstep
from conftest import corpus_file, read_ele, read_node
from mesh_checks import centroids, min_angles_deg, signed_areas

SQUARE = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
SQUARE_SEGMENTS = np.array([[0, 1], [1, 2], [2, 3], [3, 0]])


def poly_arguments(path):
    d = meshstep.read_poly(path)
    return dict(vertices=d["vertices"], segments=d.get("segments"), holes=d.get("holes"), regions=d.get("regions"),
                segment_markers=d.get("segment_markers"), vertex_markers=d.get("vertex_markers"))


def test_stats_are_the_command_lines_stats_json(cli, tmp_path):
    poly = corpus_file("guitar.poly")
    out = cli("refine", poly, "--algorithm", "lepp-centroid", "--min-angle", "28", "--stats", "json", "-q",
              "-o", tmp_path / "g")
    expected = json.loads(out.stdout.strip().splitlines()[-1])
    mesh = meshstep.refine(**poly_arguments(poly), algorithm="lepp-centroid", min_angle=28)
    for key, value in expected.items():
        if key in ("input", "ms"):
            continue
        if isinstance(value, float):  # printed with 9 significant digits
            assert mesh.stats[key] == pytest.approx(value, rel=1e-8), key
        else:
            assert mesh.stats[key] == value, key
    assert set(mesh.stats["ms"]) >= {"triangulate", "refine", "phases"}
    assert mesh.stats["vertices"] == len(mesh.vertices)
    assert mesh.stats["triangles"] == len(mesh.triangles)


def test_min_angle_and_max_area_are_met():
    mesh = meshstep.refine(SQUARE, SQUARE_SEGMENTS, min_angle=30, max_area=0.01)
    assert mesh.stats["bounds_met"]
    assert min_angles_deg(mesh.vertices, mesh.triangles).min() >= 30
    areas = signed_areas(mesh.vertices, mesh.triangles)
    assert areas.max() <= 0.01 and np.isclose(areas.sum(), 1.0)
    assert mesh.vertices.dtype == np.float64 and mesh.triangles.shape[1] == 3
    assert mesh.markers.shape == (len(mesh.vertices),)
    assert (mesh.vertices[:4] == SQUARE).all()  # input vertices first, in order


def canonical(triangles):
    """Triangles as a sorted list, each starting at its smallest vertex (orientation kept)."""
    rows = []
    for t in triangles.tolist():
        k = t.index(min(t))
        rows.append(tuple(t[k:] + t[:k]))
    return sorted(rows)


def test_each_algorithm_and_both_data_structures_run():
    for algorithm in meshstep.algorithms():
        bounds = dict(max_area=0.01) if algorithm in ("lepp-bisection", "midpoint-area") else dict(min_angle=25)
        tds = meshstep.refine(SQUARE, SQUARE_SEGMENTS, algorithm=algorithm, **bounds)
        dcel = meshstep.refine(SQUARE, SQUARE_SEGMENTS, algorithm=algorithm, ds="dcel", **bounds)
        assert tds.stats["algorithm"] == algorithm
        assert dcel.stats["ds"] == "dcel"
        # The same vertices and triangles (a triangle may start at another corner).
        assert (tds.vertices == dcel.vertices).all(), algorithm
        assert canonical(tds.triangles) == canonical(dcel.triangles), algorithm


def test_other_options_by_keyword():
    mesh = meshstep.refine(SQUARE, SQUARE_SEGMENTS, max_area=1e-4, max_triangles=500)
    assert mesh.stats["stopped_by_cap"]
    with pytest.raises(ValueError, match="unknown option --no-such-option"):
        meshstep.refine(SQUARE, no_such_option=1)
    with pytest.raises(ValueError, match="--min-angle"):
        meshstep.refine(SQUARE, min_angle=-3)
    with pytest.raises(ValueError, match="algorithm|no-such"):
        meshstep.refine(SQUARE, algorithm="no-such")


def test_is_bad_refines_where_the_callable_says():
    calls = []

    def is_bad(vertices, area):
        calls.append(vertices.shape)
        return vertices[:, 0].mean() < 0.5 and area > 1e-3

    mesh = meshstep.refine(SQUARE, SQUARE_SEGMENTS, min_angle=20, is_bad=is_bad)
    assert calls and calls[0] == (3, 2)
    c = centroids(mesh.vertices, mesh.triangles)
    areas = signed_areas(mesh.vertices, mesh.triangles)
    assert areas[c[:, 0] < 0.5].max() <= 1e-3
    assert areas[c[:, 0] > 0.6].max() > 1e-3
    assert mesh.stats["bounds_met"]


def test_an_exception_in_is_bad_comes_through():
    def is_bad(vertices, area):
        raise ZeroDivisionError("from the criterion")

    with pytest.raises(ZeroDivisionError, match="from the criterion"):
        meshstep.refine(SQUARE, SQUARE_SEGMENTS, is_bad=is_bad)


def test_a_box_region_is_refined_alone():
    mesh = meshstep.refine(SQUARE, SQUARE_SEGMENTS, max_area=1e-3, region=(0.0, 0.0, 0.5, 0.5))
    c = centroids(mesh.vertices, mesh.triangles)
    areas = signed_areas(mesh.vertices, mesh.triangles)
    inside = (c[:, 0] <= 0.5) & (c[:, 1] <= 0.5)
    assert areas[inside].max() <= 1e-3
    assert areas[~inside].max() > 1e-3
    as_list = meshstep.refine(SQUARE, SQUARE_SEGMENTS, max_area=1e-3, region=[0.0, 0.0, 0.5, 0.5])
    assert (as_list.triangles == mesh.triangles).all()


def test_a_polygon_region():
    triangle = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
    mesh = meshstep.refine(SQUARE, SQUARE_SEGMENTS, max_area=1e-3, region=triangle)
    c = centroids(mesh.vertices, mesh.triangles)
    areas = signed_areas(mesh.vertices, mesh.triangles)
    inside = c[:, 0] + c[:, 1] <= 1.0
    assert areas[inside].max() <= 1e-3
    assert areas[~inside].max() > 1e-3


def test_a_recipe_runs_its_operations_in_order(tmp_path):
    text = "# coarse, then fine in a corner\nrefine --min-angle 25\nrefine --max-area 1e-3 --region 0,0,0.5,0.5\n"
    from_text = meshstep.refine(SQUARE, SQUARE_SEGMENTS, recipe=text)
    (tmp_path / "two.recipe").write_text(text)
    from_file = meshstep.refine(SQUARE, SQUARE_SEGMENTS, recipe=pathlib.Path(tmp_path / "two.recipe"))
    assert (from_text.triangles == from_file.triangles).all()
    assert list(from_text.stats["ms"]["phases"]) == ["refine", "2:refine"]
    with pytest.raises(ValueError, match="recipe:2: .*--max-area"):
        meshstep.refine(SQUARE, SQUARE_SEGMENTS, recipe="refine --min-angle 25\nrefine --max-area -1\n")
    with pytest.raises(ValueError, match="do not also give min_angle"):
        meshstep.refine(SQUARE, SQUARE_SEGMENTS, recipe=text, min_angle=20)


def test_a_recipe_gives_what_meshstep_run_gives_and_records_one_log(cli, tmp_path):
    # A 5-degree wedge: both operations leave triangles at its tip alone, and the stats add
    # up both operations' counts as the command line's do.
    wedge = np.array([[0.0, 0.0], [10.0, 0.0], [10 * np.cos(np.radians(5)), 10 * np.sin(np.radians(5))]])
    segments = np.array([[0, 1], [1, 2], [2, 0]])
    text = "refine --min-angle 20\nrefine --min-angle 28 --max-area 0.5\n"
    log = tmp_path / "chain.mslog"
    mesh = meshstep.refine(wedge, segments, recipe=text, record=log)
    poly = tmp_path / "wedge.poly"
    poly.write_text("3 2 0 0\n" + "".join(f"{i + 1} {x!r} {y!r}\n" for i, (x, y) in enumerate(wedge.tolist())) +
                    "3 0\n1 1 2\n2 2 3\n3 3 1\n0\n")
    (tmp_path / "chain.recipe").write_text(text)
    out = cli("run", tmp_path / "chain.recipe", poly, "--stats", "json", "-q", "-o", tmp_path / "c")
    expected = json.loads(out.stdout.strip().splitlines()[-1])
    first, xy, _ = read_node(tmp_path / "c.node")
    assert np.array(xy).tolist() == mesh.vertices.tolist()
    assert read_ele(tmp_path / "c.ele", first) == [tuple(t) for t in mesh.triangles.tolist()]
    for key in ("skipped_small_angle", "steiner", "segment_splits", "below_min_angle", "bounds_met"):
        assert mesh.stats[key] == expected[key], key
    alone = meshstep.refine(wedge, segments, min_angle=20)
    assert 0 < alone.stats["skipped_small_angle"] < mesh.stats["skipped_small_angle"]
    # One log holds both operations and ends at the mesh returned.
    cli("log", "verify", log)
    cli("log", "mesh", log, "--step", "-1", "-o", tmp_path / "last")
    first, xy, _ = read_node(tmp_path / "last.node")
    assert np.array(xy).tolist() == mesh.vertices.tolist()


def test_record_writes_a_log_the_command_line_verifies(cli, tmp_path):
    log = tmp_path / "run.mslog"
    mesh = meshstep.refine(SQUARE, SQUARE_SEGMENTS, min_angle=30, record=log)
    assert log.exists() and not (tmp_path / "run.mslog.partial").exists()
    cli("log", "verify", log)
    # The log's last moment is the mesh returned.
    cli("log", "mesh", log, "--step", "-1", "-o", tmp_path / "last")
    first, xy, _ = read_node(tmp_path / "last.node")
    assert np.array(xy).tolist() == mesh.vertices.tolist()
    assert read_ele(tmp_path / "last.ele", first) == [tuple(t) for t in mesh.triangles.tolist()]


def test_to_meshio_round_trip(tmp_path):
    import meshio

    regions = np.array([[0.5, 0.5, 3.0, 0.0]])
    mesh = meshstep.refine(SQUARE, SQUARE_SEGMENTS, regions=regions, min_angle=25)
    m = mesh.to_meshio()
    path = tmp_path / "square.vtu"
    m.write(path)
    back = meshio.read(path)
    assert (back.cells_dict["triangle"] == mesh.triangles).all()
    assert np.allclose(back.points[:, :2], mesh.vertices)
    assert (back.cell_data["region"][0] == 3.0).all()


def test_refine_of_a_corpus_file_meets_its_bounds():
    poly = corpus_file("A.poly")
    mesh = meshstep.refine(**poly_arguments(poly), min_angle=30)
    assert mesh.stats["bounds_met"] or mesh.stats["bad_near_small_input_angle"] == mesh.stats["bad_triangles"]
    assert (signed_areas(mesh.vertices, mesh.triangles) > 0).all()
