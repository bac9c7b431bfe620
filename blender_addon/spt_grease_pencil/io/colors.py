"""sRGB 8-bit <-> scene-linear float conversion that round-trips all 256 values exactly.

Grease Pencil stores vertex colours scene-linear as float32. Import maps each 8-bit value to the
float32 nearest its linear value (table LINEAR); export maps a float back to the 8-bit value whose
sRGB interval holds it: the boundaries are the linear values of (k + 0.5) / 255, so every table
entry maps back to its own index and edited colours round to the nearest sRGB code."""

import bisect
import struct


def srgb_to_linear(c: float) -> float:
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


def linear_to_srgb(c: float) -> float:
    if c <= 0.0031308:
        return 12.92 * c
    return 1.055 * c ** (1.0 / 2.4) - 0.055


def _f32(x: float) -> float:
    return struct.unpack("<f", struct.pack("<f", x))[0]


LINEAR = [_f32(srgb_to_linear(k / 255.0)) for k in range(256)]
# BOUNDS[k] separates code k from code k+1.
BOUNDS = [srgb_to_linear((k + 0.5) / 255.0) for k in range(255)]


def to_linear(code: int) -> float:
    return LINEAR[code]


def to_code(linear: float) -> int:
    """The 8-bit sRGB code of a scene-linear value (clamped to 0..255)."""
    return bisect.bisect_right(BOUNDS, linear)


def unit_to_code(v: float) -> int:
    """A 0..1 float (alpha, strength) to 0..255 by rounding; exact for k / 255 in float32."""
    return min(255, max(0, int(round(v * 255.0))))
