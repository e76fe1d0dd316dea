"""meshstep.terrain_tiles on a Dask LocalCluster of two workers, against the command line's
single-process tiled run, file for file."""
import numpy as np
import pytest

import meshstep


def write_grid(path, nx=65, ny=49):
    x = np.linspace(0, 4 * np.pi, nx)
    y = np.linspace(0, 3 * np.pi, ny)
    z = 50 * np.sin(x)[None, :] * np.cos(y)[:, None] + 10 * np.outer(y, np.ones(nx))
    with open(path, "w") as f:
        f.write(f"ncols {nx}\nnrows {ny}\nxllcorner 500000\nyllcorner 4000000\ncellsize 10\nNODATA_value -9999\n")
        for row in z[::-1]:  # the northernmost row first
            f.write(" ".join(f"{v:.3f}" for v in row) + "\n")


def obj_counts(path):
    lines = path.read_text().splitlines()
    return sum(l.startswith("v ") for l in lines), sum(l.startswith("f ") for l in lines)


def test_tiles_on_two_workers_are_the_single_process_runs_files(cli, tmp_path):
    distributed = pytest.importorskip("distributed")
    grid = tmp_path / "hill.asc"
    write_grid(grid)
    (tmp_path / "cli").mkdir()
    (tmp_path / "dask").mkdir()
    cli("terrain", grid, "--tile", "17", "--max-error", "0.5", "-o", tmp_path / "cli" / "hill.obj", "-q")

    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        result = meshstep.terrain_tiles(grid, tile=17, max_error=0.5, client=client,
                                        output=tmp_path / "dask" / "hill.obj")
        workers = len(client.scheduler_info()["workers"])
    assert workers == 2

    expected = sorted(p.name for p in (tmp_path / "cli").iterdir())
    assert len(expected) == 12  # 3 rows x 4 columns of tiles
    assert sorted(p.name for p in (tmp_path / "dask").iterdir()) == expected  # no staged file left
    for name in expected:
        assert (tmp_path / "dask" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name

    assert result["tiles"] == 12 and result["max_error"] <= 0.5
    assert "no crack" in result["check"]
    # The join is terrain-join's.
    cli("terrain-join", *sorted((tmp_path / "cli").iterdir()), "-o", tmp_path / "joined.obj", "-q")
    assert obj_counts(tmp_path / "joined.obj") == (len(result["vertices"]), len(result["triangles"]))


def test_bad_arguments_raise_value_error_before_any_cluster(tmp_path):
    grid = tmp_path / "hill.asc"
    write_grid(grid, 9, 9)
    with pytest.raises(ValueError, match="max_error"):
        meshstep.terrain_tiles(grid, tile=5, max_error=-1)
    with pytest.raises(ValueError, match="at least 2"):
        meshstep.terrain_tiles(grid, tile=1, max_error=1)
    with pytest.raises(ValueError, match=".obj, .off or .ply"):
        meshstep.terrain_tiles(grid, tile=5, max_error=1, output=tmp_path / "x.stl")
    (tmp_path / "bad.asc").write_text("ncols 3\nnrows 3\n")
    with pytest.raises(ValueError, match="bad.asc"):
        meshstep.terrain_tiles(tmp_path / "bad.asc", tile=5, max_error=1)
