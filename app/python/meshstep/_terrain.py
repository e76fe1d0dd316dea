"""``terrain_tiles``: a height grid's tiles approximated on a Dask cluster, then joined."""
from __future__ import annotations

import os
from typing import Any, Dict, Optional, Union

import numpy as np

from . import _meshstep

__all__ = ["terrain_tiles", "tile_path"]


def tile_path(output: str, row: int, column: int) -> str:
    """Where tile (row, column) of output OUT.EXT goes: OUT.rR-cC.EXT, as ``meshstep terrain
    --tile`` names it."""
    folder, name = os.path.split(output)
    stem, ext = os.path.splitext(name)
    if not stem:  # ".obj" alone: no extension to keep apart
        stem, ext = name, ""
    return os.path.join(folder, f"{stem}.r{row}-c{column}{ext}")


def _tile(index, grid, tile, max_error, algorithm, output):
    """One tile, on a worker: its TIN, and its file written (staged, then renamed)."""
    from meshstep import _meshstep as core  # imported on the worker

    row, column = index
    final = tile_path(output, row, column) if output else ""
    staged = ""
    if final:
        folder, name = os.path.split(final)
        staged = os.path.join(folder, f".{name}.{os.getpid()}.partial{os.path.splitext(name)[1]}")
    try:
        result = core.terrain_tile(grid, tile, row, column, max_error, algorithm, final, staged)
        if final:
            os.replace(staged, final)
    finally:
        if staged and os.path.exists(staged):
            os.remove(staged)
    result["row"], result["column"] = row, column
    return result


def terrain_tiles(grid: Union[str, "os.PathLike[str]"], tile: int, max_error: float,
                  client: Any = None, output: Optional[Union[str, "os.PathLike[str]"]] = None,
                  algorithm: str = "lepp-surface", n_workers: int = 2) -> Dict[str, Any]:
    """Approximate a height grid tile by tile on a Dask cluster, then join and check the tiles.

    Each tile of ``tile`` x ``tile`` samples (neighbours share a row or column of samples)
    is approximated within ``max_error`` height units independently, as ``meshstep terrain
    GRID --tile N --tile-index R,C --max-error E`` does, on whichever worker Dask gives it;
    the tiles' sides are simplified the same way by both neighbours, so they weld without
    cracks. With ``output`` (OUT.obj, .off or .ply), each worker writes its tile to
    OUT.rR-cC.EXT, the files ``meshstep terrain --tile`` writes, byte for byte.

    Parameters
    ----------
    grid: a height grid file (ESRI ASCII .asc, PNG, or what GDAL reads), on a path every
        worker can read.
    tile: samples a tile side, at least 2.
    max_error: the vertical error bound, in height units.
    client: a ``dask.distributed.Client``; None: a ``LocalCluster`` of ``n_workers`` worker
        processes, one thread each, made for the call and closed after it.
    algorithm: ``lepp-surface`` (improved, as the command line does by default) or ``greedy``.

    Returns
    -------
    dict: ``vertices`` (n, 3) and ``triangles`` (t, 3) of the joined surface (shared vertices
    welded), ``tiles`` (how many), ``max_error`` (the largest of the tiles'), ``check`` (the
    join check of ``meshstep terrain-join``, in words).

    Raises
    ------
    ValueError: for a bad grid or arguments, and when the joined tiles fail the check (a crack
        or an overlap: never expected).
    """
    grid = os.fspath(grid)
    output = os.fspath(output) if output is not None else ""
    if not (isinstance(max_error, (int, float)) and max_error > 0 and np.isfinite(max_error)):
        raise ValueError(f"max_error: must be a positive number of height units, not {max_error!r}")
    if output and os.path.splitext(output)[1].lower() not in (".obj", ".off", ".ply"):
        raise ValueError(f"{output}: tiles are written as .obj, .off or .ply")
    if output and not os.path.isdir(os.path.dirname(os.path.abspath(output))):
        raise ValueError(f"{output}: its folder does not exist")
    rows, columns = _meshstep.tile_layout(grid, int(tile))
    indices = [(r, c) for r in range(rows) for c in range(columns)]
    own = client is None
    cluster = None
    if own:
        from dask.distributed import Client, LocalCluster

        cluster = LocalCluster(n_workers=n_workers, threads_per_worker=1, processes=True,
                               dashboard_address=None)
        client = Client(cluster)
    try:
        futures = client.map(_tile, indices, grid=grid, tile=int(tile), max_error=float(max_error),
                             algorithm=algorithm, output=output, pure=False)
        results = client.gather(futures)
    finally:
        if own:
            client.close()
            cluster.close()
    results.sort(key=lambda t: (t["row"], t["column"]))
    joined = _meshstep.join_tiles([{"vertices": t["vertices"], "triangles": t["triangles"]} for t in results])
    if not joined["ok"]:
        raise ValueError(f"{grid}: the joined tiles fail the check: {joined['check']}")
    return {"vertices": joined["vertices"], "triangles": joined["triangles"], "tiles": len(results),
            "max_error": max(t["max_error"] for t in results), "check": joined["check"]}
