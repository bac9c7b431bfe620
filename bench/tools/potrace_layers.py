"""potrace per colour layer, the way people vectorize flat-colour art with it (Inkscape's "Trace
bitmap, multiple scans, colours, stacked"): quantize the frame to a palette, one bitmap per
colour, `potrace -s` each, the SVGs combined into one. Python standard library, potrace, ffmpeg.

Layers are drawn largest colour first (the largest is the background rectangle). Stacked, each
layer's bitmap holds its own pixels and those of every later layer: the later layers are drawn
over it, so potrace's smoothed edges never leave a gap between two colours. Not stacked, each
bitmap holds its colour's pixels only (smaller files, background showing through the seams).
"""
import re
import subprocess

HEX = re.compile(r'fill="#([0-9a-fA-F]{6})"')
GROUP = re.compile(r'<g transform="([^"]*)"[^>]*>(.*?)</g>', re.S)


def svg_palette(svg_text, most=255):
    """The colours of the background <rect>, the <polygon>s and the lines of an SVG (spt export
    of a cartoon frame: its palette), as RGB, at most `most` of them: colours within 6 levels of a
    more frequent one join it (a traced ink colour differs a little from region to region)."""
    count, background = {}, True
    for line in svg_text.splitlines():
        # The first <rect> is the canvas; later ones are stamps (the residual, not the palette).
        # Lines (curves) are a stroked <polyline> or a <g> of discs and quads.
        if line.startswith("<polyline"):
            m = re.search(r'stroke="#([0-9a-fA-F]{6})"', line)
            if m:
                c = tuple(int(m.group(1)[i:i + 2], 16) for i in (0, 2, 4))
                count[c] = count.get(c, 0) + 1
            continue
        if line.startswith("<polygon") or line.startswith("<g fill") or (background and line.startswith("<rect")):
            background = background and not line.startswith("<rect")
            m = HEX.search(line)
            if m:
                c = tuple(int(m.group(1)[i:i + 2], 16) for i in (0, 2, 4))
                count[c] = count.get(c, 0) + 1
    kept = []
    for c in sorted(count, key=lambda c: (-count[c], c)):
        if all(max(abs(a - b) for a, b in zip(c, k)) > 6 for k in kept):
            kept.append(c)
    return sorted(kept[:most])


def read_rgb(png):
    """(width, height, rgb24 bytes) of an image, through ffmpeg."""
    probe = subprocess.run(["ffprobe", "-v", "error", "-select_streams", "v:0", "-show_entries",
                            "stream=width,height", "-of", "csv=p=0", png],
                           stdout=subprocess.PIPE, text=True, check=True).stdout.strip().split(",")
    w, h = int(probe[0]), int(probe[1])
    raw = subprocess.run(["ffmpeg", "-loglevel", "error", "-i", png, "-f", "rawvideo", "-pix_fmt", "rgb24", "-"],
                         stdout=subprocess.PIPE, check=True).stdout
    return w, h, raw


def quantize(raw, palette):
    """Per pixel, the index of its nearest palette colour (bytes; palette of at most 255)."""
    near = {}
    out = bytearray(len(raw) // 3)
    for i in range(len(out)):
        c = raw[3 * i:3 * i + 3]
        k = near.get(c)
        if k is None:
            r, g, b = c
            k = min(range(len(palette)),
                    key=lambda j: (palette[j][0] - r) ** 2 + (palette[j][1] - g) ** 2 + (palette[j][2] - b) ** 2)
            near[c] = k
        out[i] = k
    return bytes(out)


def trace(png, palette, stacked=True):
    """The combined SVG text of `png` traced per colour of `palette`."""
    w, h, raw = read_rgb(png)
    labels = quantize(raw, palette)
    area = [labels.count(k) for k in range(len(palette))]
    order = [k for k in sorted(range(len(palette)), key=lambda k: -area[k]) if area[k]]
    rank = bytes(order.index(k) if area[k] else 255 for k in range(len(palette)))
    ranked = labels.translate(rank + bytes(256 - len(rank)))
    hexes = ["#%02x%02x%02x" % palette[k] for k in order]
    parts = ['<svg xmlns="http://www.w3.org/2000/svg" version="1.1" width="%d" height="%d" viewBox="0 0 %d %d">\n'
             % (w, h, w, h), '<rect width="%d" height="%d" fill="%s"/>\n' % (w, h, hexes[0])]
    for li in range(1, len(order)):
        # Black (0, traced) where the pixel's colour ranks li (or later, stacked), white elsewhere.
        table = bytes(0 if (r == li or (stacked and li < r < 255)) else 255 for r in range(256))
        pgm = b"P5\n%d %d\n255\n" % (w, h) + ranked.translate(table)
        svg = subprocess.run(["potrace", "-s", "-o", "-", "-"], input=pgm, stdout=subprocess.PIPE,
                             check=True).stdout.decode()
        m = GROUP.search(svg)
        if not m or not m.group(2).strip():
            continue
        parts.append('<g transform="%s" fill="%s" stroke="none">%s</g>\n' % (m.group(1), hexes[li], m.group(2).strip()))
    parts.append("</svg>\n")
    return "".join(parts)
