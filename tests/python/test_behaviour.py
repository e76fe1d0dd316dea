"""Edge cases and manners: bad input is a ValueError, never a crash; long runs release the
GIL and stop on Ctrl+C."""
import os
import signal
import threading
import time

import numpy as np
import pytest

import meshstep
from mesh_checks import signed_areas

SQUARE = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
SQUARE_SEGMENTS = np.array([[0, 1], [1, 2], [2, 3], [3, 0]])


def test_empty_input_raises_value_error():
    with pytest.raises(ValueError):
        meshstep.triangulate(dict(vertices=np.zeros((0, 2))), "p")
    with pytest.raises(ValueError):
        meshstep.triangulate(dict(vertices=[]), "")
    with pytest.raises(ValueError):
        meshstep.refine(np.zeros((0, 2)))
    with pytest.raises(ValueError, match="vertices"):
        meshstep.triangulate({}, "p")


def test_one_triangle():
    t = meshstep.triangulate(dict(vertices=[[0, 0], [1, 0], [0, 1]]), "")
    assert t["triangles"].tolist() == [[0, 1, 2]]
    # Its smallest angle is 45 degrees: nothing to refine at 30.
    same = meshstep.refine([[0, 0], [1, 0], [0, 1]], [[0, 1], [1, 2], [2, 0]], min_angle=30)
    assert same.triangles.tolist() == [[0, 1, 2]] and same.stats["steiner"] == 0
    # An area bound refines it.
    small = meshstep.refine([[0, 0], [1, 0], [0, 1]], [[0, 1], [1, 2], [2, 0]], min_angle=30, max_area=0.05)
    areas = signed_areas(small.vertices, small.triangles)
    assert len(small.triangles) > 10 and np.isclose(areas.sum(), 0.5) and areas.max() <= 0.05


def test_collinear_points_raise_value_error():
    with pytest.raises(ValueError):
        meshstep.triangulate(dict(vertices=[[0, 0], [1, 1], [2, 2]]), "")


def test_duplicate_vertices_are_merged_not_a_crash():
    v = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [1, 1], [0, 0]], float)
    t = meshstep.triangulate(dict(vertices=v), "")
    assert len(t["vertices"]) == 6  # listed, as given
    used = set(t["triangles"].ravel().tolist())
    assert not {4, 5} & used and len(t["triangles"]) == 2
    # A segment to a duplicate is a segment to the vertex it duplicates.
    closed = meshstep.triangulate(dict(vertices=v, segments=[[0, 1], [1, 2], [2, 3], [3, 5]]), "pq")
    assert np.isclose(signed_areas(closed["vertices"], closed["triangles"]).sum(), 1.0)


def test_a_hole_outside_the_domain_changes_nothing():
    inside = meshstep.triangulate(dict(vertices=SQUARE, segments=SQUARE_SEGMENTS), "pq")
    outside = meshstep.triangulate(dict(vertices=SQUARE, segments=SQUARE_SEGMENTS, holes=[[5.0, 5.0]]), "pq")
    assert (inside["triangles"] == outside["triangles"]).all()


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_coordinates_that_are_not_finite_raise_value_error(bad):
    v = SQUARE.copy()
    v[2, 1] = bad
    with pytest.raises(ValueError, match="finite"):
        meshstep.triangulate(dict(vertices=v), "")
    with pytest.raises(ValueError, match="finite"):
        meshstep.refine(v, SQUARE_SEGMENTS)


@pytest.mark.parametrize("tri,what", [
    (dict(vertices=np.zeros((4, 3))), "vertices.*shape \\(n, 2\\).*\\(4, 3\\)"),
    (dict(vertices=SQUARE, segments=[[0, 1, 2]]), "segments.*shape"),
    (dict(vertices=SQUARE, segments=[[0, 1.5]]), "whole number"),
    (dict(vertices=SQUARE, regions=[[0.5, 0.5, 1.0]]), "regions"),
    (dict(vertices=SQUARE, segments=SQUARE_SEGMENTS, segment_markers=[1, 2]), "segment_markers.*4 rows"),
    (dict(vertices=SQUARE, vertex_markers=[1, 2, 3]), "vertex_markers.*4 rows"),
    (dict(vertices="not numbers"), "vertices"),
    (dict(vertices=SQUARE, holes=[1.0, 2.0]), "holes"),
])
def test_wrong_arrays_raise_value_error_naming_them(tri, what):
    with pytest.raises(ValueError, match=what):
        meshstep.triangulate(tri, "p")


def test_wrong_shapes_in_refine():
    with pytest.raises(ValueError, match="segments"):
        meshstep.refine(SQUARE, [[0, 1, 2, 3]])
    with pytest.raises(ValueError, match="region"):
        meshstep.refine(SQUARE, SQUARE_SEGMENTS, region=[[0, 0], [1, 1]])
    with pytest.raises(TypeError):
        meshstep.triangulate(dict(vertices=SQUARE), 30)


def test_repeated_calls_in_a_loop():
    rng = np.random.default_rng(7)
    for _ in range(200):
        points = rng.random((50, 2))
        t = meshstep.triangulate(dict(vertices=points), "q")
        assert (signed_areas(t["vertices"], t["triangles"]) > 0).all()


def test_integer_and_float32_arrays_are_converted():
    t = meshstep.triangulate(dict(vertices=np.array([[0, 0], [2, 0], [2, 2], [0, 2]], np.int32)), "")
    assert t["vertices"].dtype == np.float64 and len(t["triangles"]) == 2
    f = meshstep.triangulate(dict(vertices=SQUARE.astype(np.float32)[::-1]), "")  # not contiguous
    assert len(f["triangles"]) == 2


def test_the_gil_is_released_during_a_run():
    counter = [0]
    stop = threading.Event()

    def count():
        while not stop.is_set():
            counter[0] += 1

    thread = threading.Thread(target=count)
    thread.start()
    try:
        time.sleep(0.05)
        before = counter[0]
        meshstep.refine(SQUARE, SQUARE_SEGMENTS, max_area=2e-6)  # about 2 s
        during = counter[0] - before
    finally:
        stop.set()
        thread.join()
    assert during > 100_000  # the other thread ran meanwhile


def test_ctrl_c_stops_a_long_run_with_keyboard_interrupt():
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    started = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            # Some 60 s and 10M triangles if nothing stopped it (capped at 4M as a safety net).
            meshstep.refine(SQUARE, SQUARE_SEGMENTS, max_area=1e-7, max_triangles=4_000_000)
    finally:
        timer.cancel()
    assert time.monotonic() - started < 5.0
