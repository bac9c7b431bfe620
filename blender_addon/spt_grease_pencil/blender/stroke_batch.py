"""StrokeBatch: the strokes of one Grease Pencil frame of one layer, as flat numpy arrays.

This is what the importer hands a backend (gp_v2.fill_frame, gp_v3.fill_frame): no bpy here, so
both data models get exactly the same numbers, and the v3 backend can write every attribute of a
frame with one foreach_set each.

Per stroke (n): shape QUAD / LINE / FILL (a template quad, a curve, a polygon), counts (its
number of points), material (index into the object's materials), fill (n, 4) scene-linear RGBA
(quads and polygons; A = 1: the vertex fill colour replaces the material's), ordinal (its index in
the file frame's drawing order), set_hint (stroke set of a stamp), alpha (0..255, quads).
Per point (m = counts.sum(), stroke after stroke): co (m, 3) float32 metres in the object's XZ
plane; width (m,) px, opacity (m,) 0..1 and vcol (m, 4) scene-linear RGBA (curve points; for
other shapes 0, 1 and 0).
"""

from dataclasses import dataclass

import numpy as np

QUAD, LINE, FILL = 0, 1, 2


@dataclass
class StrokeBatch:
    shape: np.ndarray
    counts: np.ndarray
    co: np.ndarray
    width: np.ndarray
    opacity: np.ndarray
    vcol: np.ndarray
    material: np.ndarray
    fill: np.ndarray
    ordinal: np.ndarray
    set_hint: np.ndarray
    alpha: np.ndarray

    def __len__(self):
        return int(self.shape.shape[0])

    def offsets(self) -> np.ndarray:
        """(n + 1,) start of each stroke's points in co, then the total."""
        out = np.zeros(len(self) + 1, dtype=np.int64)
        np.cumsum(self.counts, out=out[1:])
        return out


def point_index(starts: np.ndarray, counts: np.ndarray) -> np.ndarray:
    """The flat point indices start[i] .. start[i] + counts[i] - 1 of every i, in order, without
    a Python loop (the gather of the importer and the slices of the v3 reader)."""
    counts = np.asarray(counts, dtype=np.int64)
    total = int(counts.sum())
    if total == 0:
        return np.zeros(0, dtype=np.int64)
    run_start = np.zeros(counts.shape[0], dtype=np.int64)
    np.cumsum(counts[:-1], out=run_start[1:])
    return np.repeat(np.asarray(starts, dtype=np.int64) - run_start, counts) + np.arange(total, dtype=np.int64)
