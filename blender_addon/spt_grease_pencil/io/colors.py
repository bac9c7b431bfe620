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


# ---- colour encoding 1 (format 1.3): 16-bit half-float codes of scene-linear light ----
#
# Grease Pencil colours are scene-linear float32 already, and every half float is exactly a
# float32, so import puts each code's value in as it is and export takes the nearest code back:
# a colour that was not edited returns to its own code, bit for bit (SPEC.md 4, 8.6).

MAX_HALF_CODE = 0x7BFF   # 65504, the largest finite half


def half_to_float(codes):
    """Codes 0..0x7BFF to their exact values (float32 numpy array of the same shape)."""
    import numpy as np
    return np.asarray(codes, dtype=np.int64).astype(np.uint16).view(np.float16).astype(np.float32)


def float_to_half(values):
    """The nearest code (ties to even) of each linear value: negatives, -0 and NaN give 0, values
    above 65504 (and infinity) give 0x7BFF. int64 numpy array of the same shape."""
    import numpy as np
    v = np.asarray(values, dtype=np.float64)
    v = np.where(np.isnan(v) | (v <= 0.0), 0.0, np.minimum(v, 65504.0))
    # numpy converts float64 to float16 with one correct rounding (to nearest, ties to even).
    return v.astype(np.float16).view(np.uint16).astype(np.int64)


def values_to_linear(values, linear: bool):
    """A file's colour values (8-bit sRGB, or half codes when `linear`) as scene-linear float32."""
    import numpy as np
    if linear:
        return half_to_float(values)
    return np.asarray(LINEAR, dtype=np.float32)[np.asarray(values, dtype=np.int64)]


def linear_to_values(lin, linear: bool):
    """Scene-linear floats as a file's colour values: half codes when `linear`, else the 8-bit
    sRGB values whose intervals hold them (the exact inverse of the import table)."""
    import numpy as np
    if linear:
        return float_to_half(lin)
    return np.searchsorted(np.asarray(BOUNDS, dtype=np.float64), np.asarray(lin, dtype=np.float64),
                           side='right').astype(np.int64)
