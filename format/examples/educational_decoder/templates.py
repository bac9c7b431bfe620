"""Range-coded bitmap template samples, TMPL coding 1 (SPEC.md 7.6)."""
from .range_coder import RangeDecoder, Res8, bits


def med(a, b, c):
    """The LOCO-I median predictor."""
    if c >= max(a, b):
        return min(a, b)
    if c <= min(a, b):
        return max(a, b)
    return a + b - c


def decode_template_samples(stream, width, height):
    rc = RangeDecoder(stream, "TMPL samples")
    ctx = [Res8() for _ in range(8)]
    s = [[0] * width for _ in range(height)]
    for y in range(height):
        for x in range(width):
            a = s[y][x - 1] if x > 0 else 0
            b = s[y - 1][x] if y > 0 else 0
            c = s[y - 1][x - 1] if x > 0 and y > 0 else 0
            pred = med(a, b, c)
            q = min(7, bits(abs(a - c) + abs(b - c)))
            s[y][x] = (pred + rc.res8(ctx[q])) % 256
    rc.end()
    return bytes(v for row in s for v in row)
