"""Decoder-replayed candidates, frame coding 2 (SPEC.md 7.7, format 1.1; lead strokes 1.5).

The decoder draws the painter's candidate strokes from a seeded generator, and the body codes
which of them were kept, plus the orientations and colours, predicted from the canvas painted
so far. So this module renders (render.py) while it decodes."""
from .errors import fail
from .range_coder import Context, RangeDecoder, Res8, Tree, UInt, bits, contexts
from .ranged import BodyPrefix, StrokeStream, decode_edits
from .render import Canvas, draw, stamp_coverage
from .strokes import Stamp, check_stroke, remove_and_move

MASK64 = (1 << 64) - 1


# ---- 7.7.1 generator ----

def mix64(z):
    z = (z + 0x9E3779B97F4A7C15) & MASK64
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK64
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK64
    return z ^ (z >> 31)


def draw_value(seed, s, n, stream):
    h = mix64(seed ^ 0x5350545061696E74)
    h = mix64(h ^ ((s << 56) & MASK64) ^ stream)
    return mix64(h ^ n)


def below(r, m):
    return (r * m) >> 64


# ---- 7.7.4 canvas predictions ----

def footprint_mean(canvas, header, templates, stamp):
    """The colour prediction and the activity class of an opaque stamp on the canvas."""
    sa, sk, cells = 0, [0, 0, 0], []  # Sa, Sk and the covered pixels
    for x, y, a in stamp_coverage(header, templates, stamp):
        if a > 0:
            px = canvas.pixel(x, y)
            cells.append((a, px))
            sa += a
            for k in range(3):
                sk[k] += a * px[k]
    if sa == 0:
        return tuple(header.background), 0
    P = tuple((sk[k] + sa // 2) // sa for k in range(3))
    dev = sum(a * abs(px[1] - P[1]) for a, px in cells)
    act = 0 if dev < 2 * sa else 1 if dev < 6 * sa else 2 if dev < 16 * sa else 3
    return P, act


def edge_orientation(canvas, header, px, py):
    """The predicted orientation o* and the strength class of the canvas around (px, py)."""
    W, H = header.width, header.height

    def lum(x, y):
        r, g, b = canvas.pixel(min(max(x, 0), W - 1), min(max(y, 0), H - 1))
        return r + 2 * g + b

    jxx = jyy = jxy = 0
    for y in range(py - 3, py + 4):
        for x in range(px - 3, px + 4):
            gx = (lum(x + 1, y - 1) + 2 * lum(x + 1, y) + lum(x + 1, y + 1)
                  - lum(x - 1, y - 1) - 2 * lum(x - 1, y) - lum(x - 1, y + 1))
            gy = (lum(x - 1, y + 1) + 2 * lum(x, y + 1) + lum(x + 1, y + 1)
                  - lum(x - 1, y - 1) - 2 * lum(x, y - 1) - lum(x + 1, y - 1))
            jxx += gx * gx
            jyy += gy * gy
            jxy += gx * gy
    Ja, Jb = jxx - jyy, 2 * jxy
    Js = abs(Ja) + abs(Jb)
    if Js == 0:
        return 0, 0
    strength = 1 if bits(Js) < 20 else 2 if bits(Js) < 25 else 3
    best, best_score = 0, None
    for k, (C, S) in enumerate(header.orientations):
        score = -(Ja * (C * C - S * S) + Jb * 2 * C * S)
        if best_score is None or score > best_score:
            best, best_score = k, score
    return best, strength


# ---- 7.7.2 candidate domain and 7.7.5 region syntax ----

def decode_domain(rc, cx, W, H):
    """Decodes a set's region and returns its domain: the pixels (x, y) in raster order."""
    inside = [[True] * W for _ in range(H)]
    if rc.flag(cx["use_rects"]):
        n = 1 + rc.uint(cx["rect_count"])
        if n > 4096:
            fail("Corrupt", f"{rc.what}: {n} rectangles")
        inside = [[False] * W for _ in range(H)]
        for _ in range(n):
            x, y = rc.uint(cx["rect_xy"]), rc.uint(cx["rect_xy"])
            w, h = 1 + rc.uint(cx["rect_wh"]), 1 + rc.uint(cx["rect_wh"])
            if x >= W or y >= H or w > W - x or h > H - y:
                fail("Corrupt", f"{rc.what}: a rectangle outside the canvas")
            for yy in range(y, y + h):
                for xx in range(x, x + w):
                    inside[yy][xx] = True
    if rc.flag(cx["use_blocks"]):
        mbs = 8 + rc.uint(cx["block_size"])
        if mbs > 256:
            fail("Corrupt", f"{rc.what}: block size {mbs}")
        mcols, mrows = -(-W // mbs), -(-H // mbs)
        mask = [[0] * mcols for _ in range(mrows)]
        for r in range(mrows):
            for c in range(mcols):
                left = mask[r][c - 1] if c > 0 else 0
                up = mask[r - 1][c] if r > 0 else 0
                mask[r][c] = rc.flag(cx["mask"][left + 2 * up])
        for y in range(H):
            for x in range(W):
                inside[y][x] = inside[y][x] and mask[y // mbs][x // mbs] == 1
    return [(x, y) for y in range(H) for x in range(W) if inside[y][x]]


def decode_replay(body, key, header, templates, prev_live, what):
    """Returns (removed, motion, added) of a coding-2 body."""
    if header.alpha or header.color_encoding != 0:
        fail("Corrupt", f"{what}: frame coding 2 in a file with an alpha canvas or colour encoding 1")
    prefix = BodyPrefix(body, key, header, what)
    removed, motion, base = [], None, []
    if not key:
        if prefix.removed_count > len(prev_live):
            fail("Corrupt", f"{what}: {prefix.removed_count} removals from {len(prev_live)} strokes")
        removed, motion = decode_edits(prefix, header, len(prev_live), what)
        base = remove_and_move(prev_live, removed, motion, what)
    r = prefix.rest
    seed, flags, step = r.u64("seed"), r.u8("flags"), r.u8("color_step")
    if flags & ~7:
        fail("Unsupported", f"{what}: reserved coding-2 flags")
    if flags & 6 and header.version_minor < 5:
        fail("Corrupt", f"{what}: coding-2 flags bit 1 or 2 in a file of version 1.{header.version_minor}")
    if not 1 <= step <= 32:
        fail("Corrupt", f"{what}: colour step {step} outside 1..32")
    if prefix.added_count < 1:
        fail("Corrupt", f"{what}: a coding-2 frame without strokes")
    drawn = flags & 1

    # The starting canvas: the background and the live list after removals and motion.
    canvas = Canvas(header)
    for s in base:
        draw(canvas, header, templates, s)

    W, H = header.width, header.height
    n_orients, n_templates = len(header.orientations), len(templates)
    ob = bits(n_orients - 1)
    rc = RangeDecoder(r.take(r.left(), "stroke stream"), what + " stroke stream")
    cx = {"use_rects": Context(), "use_blocks": Context(), "rect_count": UInt(), "rect_xy": UInt(),
          "rect_wh": UInt(), "block_size": UInt(), "count": UInt(), "mask": contexts(4), "lead_count": UInt(),
          "gap": [[UInt() for _ in range(6)] for _ in range(4)],
          "orient": [[Tree(ob) for _ in range(4)] for _ in range(4)],
          "color": [[[Res8() for _ in range(4)] for _ in range(4)] for _ in range(3)]}
    added = []
    if flags & 2:  # 7.7.5 lead strokes, coded as in coding 1 and drawn at once
        L = 1 + rc.uint(cx["lead_count"])
        if L >= prefix.added_count:
            fail("Corrupt", f"{what}: {L} lead strokes leave none of {prefix.added_count} to replay")
        lead = StrokeStream(None, header, n_templates, what, rc=rc)
        for _ in range(L):
            stroke = lead.stroke()
            check_stroke(stroke, header, n_templates, what)
            added.append(stroke)
            draw(canvas, header, templates, stroke)
    domain = None
    for s in range(len(header.sets)):
        sc = min(s, 3)  # the set class
        if s == 0 or not flags & 4:  # flags bit 2: set 0's region is every set's
            domain = decode_domain(rc, cx, W, H)
        K = rc.uint(cx["count"])
        if len(added) + K > prefix.added_count:
            fail("Corrupt", f"{what}: set {s} has more strokes than added_count")
        if K > 0 and (not domain or n_templates == 0):
            fail("Corrupt", f"{what}: set {s} has strokes but no candidates")
        prev, g_prev = -1, 0
        for _ in range(K):
            gap = rc.uint(cx["gap"][sc][min(5, bits(g_prev))])
            n = prev + 1 + gap
            if n >= 1 << 48:
                fail("Corrupt", f"{what}: candidate number {n} is not below 2^48")
            prev, g_prev = n, gap
            px, py = domain[below(draw_value(seed, s, n, 1), len(domain))]
            template = below(draw_value(seed, s, n, 2), n_templates)
            if drawn:
                orient = below(draw_value(seed, s, n, 3), n_orients)
            else:
                o_star, strength = edge_orientation(canvas, header, px, py)
                d = rc.tree(cx["orient"][sc][strength])
                if d >= n_orients:
                    fail("Corrupt", f"{what}: orientation difference {d} of {n_orients}")
                orient = (o_star + d) % n_orients
            stamp = Stamp(s, template, orient, 16 * px + 8, 16 * py + 8, (0, 0, 0, 255))
            P, act = footprint_mean(canvas, header, templates, stamp)
            G = P[1] + step * rc.res8(cx["color"][0][sc][act], allow_128=True)
            R = min(max(G + P[0] - P[1], 0), 255) + step * rc.res8(cx["color"][1][sc][act], allow_128=True)
            B = min(max(G + P[2] - P[1], 0), 255) + step * rc.res8(cx["color"][2][sc][act], allow_128=True)
            if not (0 <= G <= 255 and 0 <= R <= 255 and 0 <= B <= 255):
                fail("Corrupt", f"{what}: colour off 0..255")
            stamp.rgba = (R, G, B, 255)
            added.append(stamp)
            draw(canvas, header, templates, stamp)
    if len(added) != prefix.added_count:
        fail("Corrupt", f"{what}: the sets hold {len(added)} strokes, added_count says {prefix.added_count}")
    rc.end()
    return removed, motion, added
