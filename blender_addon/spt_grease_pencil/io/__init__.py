"""The file layer: .spt stored mode and the stroke <-> Grease Pencil shape conversion.

Plain Python 3 standard library (geometry_np additionally uses numpy when present); importable
and testable without Blender."""

from .model import (AFFINE, CURVE, INTER, KEY, STAMP, Frame, Header, Limits, Motion, NeedsPack,  # noqa: F401
                    Roi, SptError, StreamInfo, Template, default_orientations)
from .reader import SptFile, apply_frames, read_bytes, read_file  # noqa: F401
from .writer import frames_from_lists, write_stored  # noqa: F401
