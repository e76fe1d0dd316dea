"""Shared fixtures of the Python tests: where the command line, the shared corpus and the
assets are (CTest passes them in the environment; defaults for a run from the checkout)."""
import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


def _path(variable, default):
    return pathlib.Path(os.environ.get(variable) or default)


BINARY = _path("MESHSTEP_BINARY", ROOT / "build" / "meshstep")
SHARED_DATA = _path("MESHSTEP_SHARED_DATA", ROOT.parent / "shared" / "data")
ASSETS = _path("MESHSTEP_ASSETS", ROOT / "assets")


@pytest.fixture
def cli():
    """Runs the meshstep command line; skips when it is not built."""
    if not BINARY.exists():
        pytest.skip(f"the meshstep program is not built ({BINARY})")

    def run(*args, check=True):
        result = subprocess.run([str(BINARY), *map(str, args)], capture_output=True, text=True)
        if check and result.returncode != 0:
            raise AssertionError(f"meshstep {' '.join(map(str, args))} exited {result.returncode}: {result.stderr}")
        return result

    return run


def corpus_file(name):
    """A file of the shared corpus (pslg/NAME) or the examples; skips, saying so, when absent."""
    for candidate in (SHARED_DATA / "pslg" / name, ASSETS / "examples" / name):
        if candidate.exists():
            return candidate
    pytest.skip(f"{name} is in neither {SHARED_DATA / 'pslg'} nor {ASSETS / 'examples'}")


def read_node(path):
    """Triangle's .node file: (first index, rows of x y, markers or None). Independent of meshstep."""
    lines = [l.split("#", 1)[0].split() for l in pathlib.Path(path).read_text().splitlines()]
    lines = [l for l in lines if l]
    count, _, attributes, has_markers = (int(v) for v in lines[0])
    rows = lines[1:1 + count]
    first = int(rows[0][0]) if rows else 0
    xy = [(float(r[1]), float(r[2])) for r in rows]
    markers = [int(r[3 + attributes]) for r in rows] if has_markers else None
    return first, xy, markers


def read_ele(path, first):
    """Triangle's .ele file: rows of three 0-based vertex indices."""
    lines = [l.split("#", 1)[0].split() for l in pathlib.Path(path).read_text().splitlines()]
    lines = [l for l in lines if l]
    count = int(lines[0][0])
    return [tuple(int(v) - first for v in r[1:4]) for r in lines[1:1 + count]]


def read_edge(path, first):
    """Triangle's .edge file: rows of (a, b, marker), 0-based."""
    lines = [l.split("#", 1)[0].split() for l in pathlib.Path(path).read_text().splitlines()]
    lines = [l for l in lines if l]
    count = int(lines[0][0])
    return [(int(r[1]) - first, int(r[2]) - first, int(r[3])) for r in lines[1:1 + count]]
