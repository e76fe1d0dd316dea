"""``Log``: a replay log written by ``meshstep ... --record`` or ``refine(record=...)``."""
from __future__ import annotations

import json
import os
from typing import Any, Dict, Iterator, List, Union

import numpy as np

from . import _meshstep

__all__ = ["Log", "Svg", "Picture", "GlUnavailable", "render"]

GlUnavailable = _meshstep.GlUnavailable


class Svg(str):
    """An SVG document (a str), shown as a picture in Jupyter."""

    def _repr_svg_(self) -> str:
        return str(self)


class Picture(np.ndarray):
    """An RGB picture: a (height, width, 3) uint8 numpy array, rows top to bottom, that
    Jupyter shows as a PNG."""

    def _repr_png_(self) -> bytes:
        return _meshstep.png_bytes(np.ascontiguousarray(self))


class Log:
    """A replay log: every step of a recorded run, to read, replay and explain.

    >>> log = Log("lesson.mslog")             # doctest: +SKIP
    >>> log.step_count, log.phases()[0]["phase"]  # doctest: +SKIP
    >>> mesh = log.mesh(45)                   # the mesh after 45 steps, numpy arrays
    >>> print(log.explain(45))                # what step 45 did, in words

    Opening checks the whole file (its header and every block's checksum); a damaged or
    foreign file raises ``ValueError`` naming where. Steps are counted from 1: ``mesh(K)``
    is the mesh after K steps (0: before the first, -1: the end), ``explain(K)`` tells step K.
    """

    def __init__(self, path: Union[str, "os.PathLike[str]"]):
        self._log = _meshstep.LogFile(os.fspath(path))

    path = property(lambda self: self._log.path, doc="The log file.")
    algorithm = property(lambda self: self._log.algorithm, doc="The run's algorithm ('triangulate', 'offcenter', ...).")
    parameters = property(lambda self: self._log.parameters, doc="The run's parameters, 'key=value' words.")
    complete = property(lambda self: self._log.complete, doc="False for a log whose run did not finish.")
    event_count = property(lambda self: self._log.event_count, doc="How many events the log holds.")
    step_count = property(lambda self: self._log.step_count, doc="How many steps the run took.")

    def __len__(self) -> int:
        return self.step_count

    def __repr__(self) -> str:
        return f"Log({self.path!r}: {self.algorithm}, {self.step_count} steps, {self.event_count} events)"

    def steps(self) -> List[Dict[str, Any]]:
        """Every step: ``step`` (from 1), ``kind`` (what it did), ``first_event``, ``end_event``."""
        return self._log.steps()

    def phases(self) -> List[Dict[str, Any]]:
        """The run's phases in order: ``phase``, ``begin_event``, ``end_event`` (None: not closed)."""
        return self._log.phases()

    def mesh(self, step: int = -1) -> Dict[str, np.ndarray]:
        """The mesh after ``step`` steps as the run's output writes it: ``vertices`` (n, 2),
        ``triangles`` (t, 3), ``segments``, ``segment_markers``, ``vertex_markers``,
        ``triangle_attributes``. Raises ``IndexError`` for a step out of range."""
        return self._log.mesh(step)

    def event(self, index: int) -> Dict[str, Any]:
        """Event ``index`` as ``meshstep log dump --jsonl`` writes it, plus ``text``, its line
        in words."""
        e = json.loads(self._log.event_json(index))
        e["text"] = self._log.describe_event(index)
        return e

    def events(self) -> Iterator[Dict[str, Any]]:
        """Every event in order (see ``event``)."""
        for index in range(self.event_count):
            yield self.event(index)

    def explain(self, step: int) -> str:
        """What step ``step`` did, as the viewer's explain panel says it: a heading, then a line
        for each thing it did (the bad triangle and its criterion, the point chosen, ...)."""
        heading, lines = self._log.explain(step)
        return "\n".join([heading, *lines])

    def render(self, step: int = -1, size: Union[int, tuple] = (800, 600), gl: str = "auto") -> Picture:
        """The moment after ``step`` steps (the mesh, and the overlays that explain the step
        just taken) drawn by meshstep's OpenGL renderer off screen, as ``meshstep render -o
        OUT.png`` draws it: a ``Picture``, an RGB numpy array of shape (height, width, 3),
        uint8, shown as a PNG in Jupyter. ``size`` is (width, height) or one number for
        both; ``gl`` is ``'auto'``, ``'egl'`` or ``'osmesa'`` (``meshstep render --gl``).

        Needs OpenGL 3.3 through EGL or OSMesa (Debian: libegl1 and a Mesa driver, or
        libosmesa6): without, raises ``GlUnavailable`` (a ``RuntimeError``) saying what was
        tried; ``svg()`` draws the same moment with no GL at all."""
        width, height = _size(size)
        if gl not in ("auto", "egl", "osmesa"):
            raise ValueError(f"gl: expected 'auto', 'egl' or 'osmesa', not {gl!r}")
        return self._log.rgb(step, width, height, gl).view(Picture)

    def svg(self, step: int = -1, size: Union[int, tuple] = (800, 600)) -> Svg:
        """The moment after ``step`` steps drawn as SVG, as ``meshstep render -o OUT.svg``
        draws it; needs no OpenGL. Shown as a picture in Jupyter."""
        width, height = _size(size)
        return Svg(self._log.svg(step, width, height))


def render(log: Union["Log", str, "os.PathLike[str]"], step: int = -1, size: Union[int, tuple] = (800, 600),
           gl: str = "auto") -> Picture:
    """``Log(log).render(step, size, gl)``: the moment after ``step`` steps of a recorded run
    as an RGB numpy array (height, width, 3); raises ``GlUnavailable`` without OpenGL."""
    return (log if isinstance(log, Log) else Log(log)).render(step, size, gl)


def _size(size: Union[int, tuple]) -> tuple:
    width, height = (size, size) if isinstance(size, int) else size
    return int(width), int(height)
