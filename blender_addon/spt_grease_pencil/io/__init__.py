"""The file layer: .spt stored mode and the stroke <-> Grease Pencil shape conversion.

Python 3 and numpy (Blender ships both), no bpy: importable and testable without Blender. One
implementation of each idea, vectorised (strokes_np.py, state_np.py, geometry.py); the
one-tuple-per-stroke oracle it is tested against lives in tests/blender/reference/."""

from .model import (AFFINE, CURVE, INTER, KEY, STAMP, Frame, Header, Limits, Motion, NeedsPack,  # noqa: F401
                    Roi, SptError, StreamInfo, Template, default_orientations)
from .reader import SptFile, read_bytes, read_file  # noqa: F401
from .writer import frames_from_lists, write_stored  # noqa: F401
