"""The .spt data model as plain Python values (format/SPEC.md sections 3-5).

Strokes are tuples so that they are cheap, hashable and comparable (the exporter diffs frames
by equality):

    stamp:  (STAMP, set, template, orient, x, y, r, g, b, a)
    affine: (AFFINE, template, tx, ty, a, b, c, d, r, g, b, a)
    curve:  (CURVE, r, g, b, a, ((x, y, width), ...))
            (CURVE, r, g, b, a, ((x, y, width), ...), n_grid)  format 1.4, n_grid 2..16
    polygon: (POLYGON, r, g, b, a, n_grid, ((x, y), ...))   format 1.2, SPEC.md 4 and 8.8

A curve's supersampling grid N (format 1.4, files with the HEAD flag curve_grid; SPEC.md 8.5)
trails its points and is left out when it is 0, so that the curves of every older file keep
their tuples (and compare equal to them); curve_tuple() and curve_grid_of() make and read it.

All positions and lengths are Q4 integers (1/16 pixel), as in the file. r, g, b are the colour
values: 8-bit sRGB in colour encoding 0, and in colour encoding 1 (format 1.3, scene-linear) the
16-bit half-float codes 0..0x7BFF, 256 * high byte + low byte (SPEC.md 4); a is the 8-bit opacity.
"""

from dataclasses import dataclass, field
from typing import List, Optional, Tuple

STAMP, AFFINE, CURVE, POLYGON = 0, 1, 2, 3
KEY, INTER = 0, 1

TEMPLATE_BITMAP, TEMPLATE_ELLIPSE, TEMPLATE_RECTANGLE, TEMPLATE_TRIANGLE = 0, 1, 2, 3
TEMPLATE_KIND_NAMES = {0: "bitmap", 1: "ellipse", 2: "rectangle", 3: "triangle"}

UNKNOWN_FRAME_COUNT = 0xFFFFFFFF

# Value ranges of section 4.
MAX_POS = 1 << 24
MAX_MATRIX = 1 << 16
MAX_CURVE_WIDTH = 1 << 16
MAX_HALF_CODE = 0x7BFF   # colour encoding 1: the largest code (65504), finite and not negative

SRGB8, LINEAR_HALF = 0, 1   # HEAD color_encoding (SPEC.md 3.1)


class SptError(Exception):
    """A file that cannot be read or written; the message names the file and byte offset."""


class NeedsPack(SptError):
    """The file holds range-coded frames: `spt pack --stored` must turn it into stored mode."""


@dataclass
class Limits:
    """Checked before anything is allocated (mirrors format/include/spt/limits.hpp)."""
    max_width: int = 16384
    max_height: int = 16384
    max_pixels: int = 1 << 28
    max_chunk_bytes: int = 1 << 30
    max_templates: int = 255
    max_template_side: int = 1024
    max_strokes_per_frame: int = 1 << 24
    max_live_strokes: int = 1 << 24
    max_curve_points: int = 1 << 16
    max_polygon_vertices: int = 1 << 16
    max_metadata_bytes: int = 1 << 24
    max_frames: int = 0xFFFFFFFE


@dataclass
class Template:
    kind: int = TEMPLATE_BITMAP
    width: int = 0
    height: int = 0
    pixels: bytes = b""  # bitmap only: width*height coverage bytes, top row first
    name: str = ""
    # Analytic kinds only: N for an N x N supersampling grid (SPEC.md 3.2, 8.4), 0 = one sample.
    supersample: int = 0


@dataclass
class Header:
    width: int = 0
    height: int = 0
    fps_num: int = 24
    fps_den: int = 1
    frame_count: int = UNKNOWN_FRAME_COUNT
    version_major: int = 1
    version_minor: int = 0
    background: Tuple[int, int, int] = (255, 255, 255)  # encoding 1: the codes' high bytes
    sets: List[Tuple[int, int]] = field(default_factory=list)          # (width, height) px
    orientations: List[Tuple[int, int]] = field(default_factory=list)  # (cos, sin) Q14
    # Format 1.3: HEAD flags bit 0 (the canvas has a premultiplied alpha channel and starts
    # transparent; background is then only what a viewer shows behind it), the colour encoding
    # and, in encoding 1, the low bytes of the background's codes.
    alpha: bool = False
    color_encoding: int = SRGB8
    background_lo: Tuple[int, int, int] = (0, 0, 0)
    # Format 1.4: HEAD flags bit 1. Every curve record carries a supersampling grid N (0 or
    # 2..16, anti-aliased edges for N >= 2); without it curves have none and are sampled at
    # pixel centres.
    curve_grid: bool = False

    @property
    def linear(self) -> bool:
        """Colour encoding 1: stroke colours are half-float codes of scene-linear light."""
        return self.color_encoding == LINEAR_HALF

    def background_values(self) -> Tuple[int, int, int]:
        """The background as stroke colours hold it: 8-bit values, or 16-bit codes (encoding 1)."""
        if self.linear:
            return tuple(256 * hi + lo for hi, lo in zip(self.background, self.background_lo))
        return tuple(self.background)

    def set_background_values(self, rgb) -> None:
        """Sets background (and background_lo in encoding 1) from 8-bit values or 16-bit codes."""
        if self.linear:
            self.background = tuple(int(c) >> 8 for c in rgb)
            self.background_lo = tuple(int(c) & 255 for c in rgb)
        else:
            self.background = tuple(int(c) for c in rgb)
            self.background_lo = (0, 0, 0)


@dataclass
class Roi:
    first_frame: int
    last_frame: int
    x: int
    y: int
    w: int
    h: int


@dataclass
class StreamInfo:
    header: Header = field(default_factory=Header)
    templates: List[Template] = field(default_factory=list)
    metadata: List[Tuple[str, str]] = field(default_factory=list)
    rois: List[Roi] = field(default_factory=list)
    # Unknown ancillary chunks (type, payload) kept in order so a rewrite can preserve them.
    extra_chunks: List[Tuple[bytes, bytes]] = field(default_factory=list)


@dataclass
class Motion:
    block_size: int
    cols: int
    rows: int
    vectors: List[Tuple[int, int]]  # Q4 (dx, dy), row-major


@dataclass
class Frame:
    index: int
    type: int = KEY
    removed: List[int] = field(default_factory=list)
    motion: Optional[Motion] = None
    added: list = field(default_factory=list)  # stroke tuples


def default_orientations(n: int = 8) -> List[Tuple[int, int]]:
    """The spec's default table: round(16384 cos(k pi/n)), round(16384 sin(k pi/n))."""
    import math
    return [(round(16384 * math.cos(k * math.pi / n)), round(16384 * math.sin(k * math.pi / n)))
            for k in range(n)]


def curve_tuple(r, g, b, a, points, grid: int = 0):
    """A curve tuple in its one form: the grid N is appended only when it is not 0."""
    return (CURVE, r, g, b, a, points) + ((grid,) if grid else ())


def curve_grid_of(s) -> int:
    """The supersampling grid N of a curve tuple (0 when it has none)."""
    return s[6] if len(s) > 6 else 0


def stroke_color(s) -> Tuple[int, int, int, int]:
    if s[0] == STAMP:
        return s[6], s[7], s[8], s[9]
    if s[0] == AFFINE:
        return s[8], s[9], s[10], s[11]
    return s[1], s[2], s[3], s[4]


def with_color(s, rgba):
    r, g, b, a = rgba
    if s[0] == STAMP:
        return s[:6] + (r, g, b, a)
    if s[0] == AFFINE:
        return s[:8] + (r, g, b, a)
    if s[0] == POLYGON:
        return (POLYGON, r, g, b, a, s[5], s[6])
    return (CURVE, r, g, b, a) + s[5:]
