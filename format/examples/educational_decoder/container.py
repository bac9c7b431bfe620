"""The container: signature, chunk framing and the HEAD and TMPL chunks (SPEC.md 2 and 3).

This decoder finds frames by scanning the chunks in order (SPEC.md 9.3); it does not use the
index (`indx`), which only speeds up seeking."""
import zlib
from dataclasses import dataclass, field

from .errors import ByteReader, DecodeError, fail
from .templates import decode_template_samples

SIGNATURE = b"\x89SPT\r\n\x1a\n"
BITMAP, ELLIPSE, RECTANGLE, TRIANGLE = 0, 1, 2, 3
# This decoder's own limits (SPEC.md 10 lets a decoder choose them): a slow decoder keeps
# canvases small.
MAX_SIDE = 16384
MAX_PIXELS = 1 << 22
MAX_CODE = 0x7BFF  # the largest colour code of encoding 1: finite, not negative (SPEC.md 4)


@dataclass
class Header:
    version_major: int = 0
    version_minor: int = 0
    width: int = 0
    height: int = 0
    fps: tuple = (0, 1)
    frame_count: int = 0
    background: tuple = (0, 0, 0)      # encoding 1: the high bytes of the three codes
    alpha: bool = False                # HEAD flags bit 0 (format 1.3): an alpha canvas
    curve_grid: bool = False           # HEAD flags bit 1 (format 1.4): curves carry a grid
    color_encoding: int = 0            # 0 8-bit sRGB, 1 scene-linear half codes (format 1.3)
    background_lo: tuple = (0, 0, 0)   # encoding 1: the low bytes of the background's codes
    sets: list = field(default_factory=list)          # (width, height) per set
    orientations: list = field(default_factory=list)  # (cos, sin) Q14 per orientation


@dataclass
class Template:
    kind: int
    grid: int = 0       # analytic kinds: the supersampling grid N (0 or 2..16)
    width: int = 0      # bitmap only
    height: int = 0
    samples: bytes = b""


@dataclass
class Chunk:
    offset: int
    type: bytes
    payload: bytes
    crc_ok: bool


def is_letter(c):
    return 0x41 <= c <= 0x5A or 0x61 <= c <= 0x7A


def read_chunks(data):
    """Yields the chunks after the signature, in order, each with whether its CRC holds. Stops
    with an error at the first chunk that is cut off or whose type is not a chunk type."""
    if data[:8] != SIGNATURE:
        fail("NotSpt", "the data does not start with the .spt signature")
    off = 8
    while off < len(data):
        if len(data) - off < 12:
            fail("Truncated", f"chunk header at offset {off} is cut off")
        length = int.from_bytes(data[off:off + 4], "little")
        ctype = data[off + 4:off + 8]
        # SPEC.md 2: the first byte is a letter, the other three letters or spaces.
        if not (is_letter(ctype[0]) and all(is_letter(c) or c == 0x20 for c in ctype[1:])):
            fail("Corrupt", f"chunk type {ctype!r} at offset {off} is not a chunk type")
        if length + 12 > len(data) - off:
            fail("Truncated", f"chunk {ctype!r} at offset {off} is cut off by the end of the file")
        payload = data[off + 8:off + 8 + length]
        crc = int.from_bytes(data[off + 8 + length:off + 12 + length], "little")
        # zlib's CRC-32 is the CRC of SPEC.md 2
        yield Chunk(off, ctype, payload, zlib.crc32(ctype + payload) == crc)
        off += length + 12


def is_critical(ctype):
    return 0x41 <= ctype[0] <= 0x5A


def decode_head(payload):
    r = ByteReader(payload, "HEAD")
    h = Header()
    h.version_major = r.u16("version_major")
    h.version_minor = r.u16("version_minor")
    if h.version_major != 1:
        fail("Unsupported", f"format major version {h.version_major}")
    flags = r.u32("flags")
    if flags & ~3:
        fail("Unsupported", "HEAD flags bits 2..31 are reserved")
    h.alpha = flags & 1 == 1
    h.curve_grid = flags & 2 == 2
    h.width = r.u32("width")
    h.height = r.u32("height")
    h.fps = (r.u32("fps_num"), r.u32("fps_den"))
    h.frame_count = r.u32("frame_count")
    h.color_encoding = r.u8("color_encoding")
    if h.color_encoding > 1:
        fail("Unsupported", f"colour encoding {h.color_encoding} is reserved")
    h.background = tuple(r.take(3, "background"))
    set_count = r.u8("set_count")
    orientation_count = r.u8("orientation_count")
    if r.u16("reserved") != 0:
        fail("Unsupported", "HEAD reserved field is not 0")
    if not 1 <= set_count <= 16 or not 1 <= orientation_count <= 64:
        fail("Corrupt", "set or orientation count out of range")
    if h.width < 1 or h.height < 1 or h.fps[0] == 0 or h.fps[1] == 0:
        fail("Corrupt", "canvas size or frame rate is 0")
    if h.width > MAX_SIDE or h.height > MAX_SIDE or h.width * h.height > MAX_PIXELS:
        fail("LimitExceeded", f"canvas {h.width}x{h.height} is above this decoder's limits")
    for _ in range(set_count):
        w, hh = r.u16("set width"), r.u16("set height")
        if not (1 <= w <= 4096 and 1 <= hh <= 4096):
            fail("Corrupt", "stamp size out of 1..4096")
        h.sets.append((w, hh))
    for _ in range(orientation_count):
        c, s = r.i16("cos"), r.i16("sin")
        if c * c + s * s > (1 << 28) + (1 << 16):
            fail("Corrupt", "orientation entry longer than unit length")
        h.orientations.append((c, s))
    if h.color_encoding == 1:
        h.background_lo = tuple(r.take(3, "background_lo"))
        if r.u8("reserved") != 0:
            fail("Unsupported", "HEAD reserved byte after background_lo is not 0")
        if any(256 * hi + lo > MAX_CODE for hi, lo in zip(h.background, h.background_lo)):
            fail("Corrupt", "a background code is above 0x7BFF")
    if (h.alpha or h.color_encoding == 1) and h.version_minor < 3:
        fail("Corrupt", "an alpha canvas or colour encoding 1 needs version_minor 3")
    if h.curve_grid and h.version_minor < 4:
        fail("Corrupt", "the curve_grid flag needs version_minor 4")
    r.end()
    return h


def decode_tmpl(payload):
    r = ByteReader(payload, "TMPL")
    kind = r.u8("kind")
    coding = r.u8("coding")
    width, height = r.u16("width"), r.u16("height")
    r.take(r.u8("name_length"), "name")  # informative only
    if kind > 3:
        fail("Unsupported", f"template kind {kind} is reserved")
    if kind != BITMAP:
        if coding == 1 or coding > 16:
            fail("Unsupported", f"supersampling grid {coding} is reserved")
        if width or height:
            fail("Corrupt", "analytic template has a size")
        r.end()
        return Template(kind, grid=coding)
    if not (1 <= width <= 1024 and 1 <= height <= 1024):
        fail("Corrupt", "bitmap template size out of 1..1024")
    rest = r.take(r.left(), "samples")
    if coding == 0:
        if len(rest) != width * height:
            fail("Corrupt", "bitmap template sample count does not match its size")
        samples = rest
    elif coding == 1:
        samples = decode_template_samples(rest, width, height)
    else:
        fail("Unsupported", f"template coding {coding} is reserved")
    return Template(kind, width=width, height=height, samples=samples)


@dataclass
class SptFile:
    header: Header
    templates: list = field(default_factory=list)
    frames: list = field(default_factory=list)  # FRAM payloads in frame order
    problem: str = ""  # why the file is incomplete, or "" when it is complete


def open_spt(data):
    """Reads the header chunks, then scans the frames (SPEC.md 9.3, recovery by scanning)."""
    chunks = read_chunks(data)
    first = next(chunks, None)
    if first is None or first.type != b"HEAD" or not first.crc_ok:
        fail("Corrupt", "the first chunk is not a valid HEAD")
    spt = SptFile(decode_head(first.payload))
    damaged = ""
    try:
        for c in chunks:
            where = f"chunk {c.type!r} at offset {c.offset}"
            if not c.crc_ok:
                # From the first FRAM on (that FRAM included), damage ends the scan.
                if spt.frames or c.type in (b"FRAM", b"IEND"):
                    spt.problem = f"{where} fails its CRC"
                    return spt
                if is_critical(c.type):
                    fail("Corrupt", f"{where} fails its CRC")
                damaged = damaged or f"{where} fails its CRC; skipped"  # loses only itself
                continue
            if c.type in (b"HEAD", b"TMPL"):
                if spt.frames:
                    spt.problem = f"{where} after the first frame"
                    return spt
                if c.type == b"HEAD":
                    fail("Corrupt", f"a second HEAD at offset {c.offset}")
                if len(spt.templates) == 255:
                    fail("Corrupt", "more than 255 TMPL chunks")
                spt.templates.append(decode_tmpl(c.payload))
            elif c.type == b"FRAM":
                if len(c.payload) < 8 or int.from_bytes(c.payload[:4], "little") != len(spt.frames):
                    spt.problem = f"{where} is not frame {len(spt.frames)}"
                    return spt
                spt.frames.append(c.payload)
            elif c.type == b"IEND":
                count = int.from_bytes(c.payload[:4], "little")
                if len(c.payload) != 12 or count != len(spt.frames) or c.offset + 24 != len(data):
                    spt.problem = f"{where} does not end the file or miscounts its frames"
                else:
                    spt.problem = damaged
                return spt
            elif is_critical(c.type):
                fail("Unsupported", f"unknown critical {where}")
            # meta, rois, indx and unknown ancillary chunks do not change decoding.
    except DecodeError as e:
        # A cut chunk ends the scan; the frames before it stay (an unknown critical chunk
        # or damage before the first frame is an error).
        if e.code == "Unsupported" or not spt.frames:
            raise
        spt.problem = str(e)
        return spt
    spt.problem = "the file ends without IEND"
    return spt
