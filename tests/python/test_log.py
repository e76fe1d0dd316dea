"""meshstep.Log: a recorded run read back."""
import numpy as np
import pytest

import meshstep
from conftest import read_ele, read_node
from png_reader import read_png

SQUARE = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
SQUARE_SEGMENTS = np.array([[0, 1], [1, 2], [2, 3], [3, 0]])


@pytest.fixture
def recorded(tmp_path):
    path = tmp_path / "square.mslog"
    mesh = meshstep.refine(SQUARE, SQUARE_SEGMENTS, min_angle=30, max_area=0.05, record=path)
    return path, mesh


def test_steps_phases_and_the_last_mesh(recorded):
    path, mesh = recorded
    log = meshstep.Log(path)
    assert log.complete and log.algorithm == "offcenter"
    steps = log.steps()
    assert len(steps) == log.step_count == len(log) > 10
    assert [s["step"] for s in steps] == list(range(1, len(steps) + 1))
    assert all(s["first_event"] < s["end_event"] for s in steps)
    assert [p["phase"] for p in log.phases()] == ["insert_vertices", "recover_segments", "carve", "refine"]
    last = log.mesh(-1)
    assert (last["vertices"] == mesh.vertices).all()
    assert (last["triangles"] == mesh.triangles).all()
    assert len(log.mesh(0)["triangles"]) == 0


def test_the_mesh_after_step_k_is_the_command_lines(cli, recorded, tmp_path):
    path, _ = recorded
    log = meshstep.Log(path)
    for k in (3, log.step_count // 2, log.step_count - 1):
        cli("log", "mesh", path, "--step", k, "-o", tmp_path / f"k{k}")
        first, xy, _ = read_node(tmp_path / f"k{k}.node")
        moment = log.mesh(k)
        assert moment["vertices"].tolist() == [list(p) for p in xy]
        assert [tuple(t) for t in moment["triangles"].tolist()] == read_ele(tmp_path / f"k{k}.ele", first)


def test_events_and_explain(recorded):
    log = meshstep.Log(recorded[0])
    events = list(log.events())
    assert len(events) == log.event_count
    assert events[0]["type"] == "phase_begin" and events[-1]["type"] == "phase_end"
    assert all(isinstance(e["text"], str) and e["text"] for e in events)
    k = log.step_count
    text = log.explain(k)
    assert text.splitlines()[0].startswith(f"step {k} of {k}")
    assert len(text.splitlines()) > 1
    assert log.explain(2) != log.explain(3)


def test_svg_is_a_picture_without_gl(recorded):
    svg = meshstep.Log(recorded[0]).svg(5, size=(320, 240))
    assert svg.startswith("<?xml") and 'width="320"' in svg and "<path" in svg
    assert svg._repr_svg_() == svg


def rendered(log, step, size):
    """log.render(step, size), or a skip saying why where no OpenGL can be had."""
    try:
        return log.render(step, size=size)
    except meshstep.GlUnavailable as e:
        assert "OpenGL" in str(e) or "EGL" in str(e) or "OSMesa" in str(e), str(e)
        pytest.skip(f"no OpenGL on this machine: {e}")


def test_render_gives_the_pixels_meshstep_render_writes(cli, recorded, tmp_path):
    path, _ = recorded
    log = meshstep.Log(path)
    picture = rendered(log, 5, (320, 240))
    assert isinstance(picture, np.ndarray) and picture.dtype == np.uint8 and picture.shape == (240, 320, 3)
    # The same moment as the command line draws it into a PNG.
    cli("render", path, "--step", 5, "--size", "320x240", "-o", tmp_path / "k5.png", "-q")
    png = read_png((tmp_path / "k5.png").read_bytes())
    assert png.shape[:2] == (240, 320)
    differing = np.abs(png[:, :, :3].astype(int) - picture.astype(int)).max(axis=2) > 8
    assert differing.mean() < 0.01, f"{differing.sum()} pixels differ from meshstep render's"
    # Another moment is another picture; Jupyter gets the same pixels as a PNG.
    assert (rendered(log, -1, (320, 240)) != picture).any()
    assert (read_png(picture._repr_png_()) == picture).all()
    assert (meshstep.render(path, 5, size=(320, 240)) == picture).all()
    with pytest.raises(ValueError, match="gl"):
        log.render(5, gl="vulkan")
    with pytest.raises(IndexError):
        log.render(log.step_count + 1)


def test_out_of_range_and_damaged_logs(recorded, tmp_path):
    log = meshstep.Log(recorded[0])
    with pytest.raises(IndexError):
        log.mesh(log.step_count + 1)
    with pytest.raises(IndexError):
        log.event(log.event_count)
    bad = tmp_path / "bad.mslog"
    bad.write_bytes(b"not a log at all\n" * 10)
    with pytest.raises(ValueError, match="bad.mslog"):
        meshstep.Log(bad)
    with pytest.raises(ValueError):
        meshstep.Log(tmp_path / "missing.mslog")
