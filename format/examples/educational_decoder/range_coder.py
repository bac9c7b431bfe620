"""The binary adaptive range decoder of SPEC.md 7.2 and the binarizations of 7.3."""
from .errors import fail


class Context:
    """One adaptive probability: p is the chance, in 1/2048, that the next bit is 0."""

    def __init__(self):
        self.p = 1024


def contexts(n):
    return [Context() for _ in range(n)]


class Tree:
    """tree(T, n): a bit-tree of n bits, contexts T[1 .. 2^n - 1]. A tree over a canvas axis can
    have 2^32 nodes, so they are made when first used."""

    def __init__(self, bits):
        self.bits = bits
        self.nodes = {}

    def node(self, m):
        if m not in self.nodes:
            self.nodes[m] = Context()
        return self.nodes[m]


class UInt:
    """Contexts of uint(U, u): 32 prefix contexts."""

    def __init__(self):
        self.prefix = contexts(32)


class SInt:
    """Contexts of sint(S, v): zero, sign and the magnitude's uint."""

    def __init__(self):
        self.zero = Context()
        self.sign = Context()
        self.mag = UInt()


class Res8:
    """Contexts of res8(R, v): zero, sign and a 3-bit class tree."""

    def __init__(self):
        self.zero = Context()
        self.sign = Context()
        self.cls = Tree(3)


class RangeDecoder:
    def __init__(self, data, what):
        self.data = data
        self.what = what
        self.pos = 0  # bytes read so far, including reads past the end (which yield 0)
        self.range = 0xFFFFFFFF
        self.code = 0
        for _ in range(4):
            self.code = (self.code << 8) | self.next_byte()

    def next_byte(self):
        b = self.data[self.pos] if self.pos < len(self.data) else 0
        self.pos += 1
        return b

    def normalise(self):
        while self.range < 1 << 24:
            self.range = (self.range << 8) & 0xFFFFFFFF
            self.code = ((self.code << 8) | self.next_byte()) & 0xFFFFFFFF

    def bit(self, ctx):
        bound = (self.range >> 11) * ctx.p
        if self.code < bound:
            self.range = bound
            ctx.p += (2048 - ctx.p) >> 5
            bit = 0
        else:
            self.code -= bound
            self.range -= bound
            ctx.p -= ctx.p >> 5
            bit = 1
        self.normalise()
        return bit

    def direct(self):
        bound = (self.range >> 11) << 10
        if self.code < bound:
            self.range = bound
            bit = 0
        else:
            self.code -= bound
            self.range -= bound
            bit = 1
        self.normalise()
        return bit

    def end(self):
        # 7.2 End: every byte of the stream must have been read.
        if self.pos < len(self.data):
            fail("Corrupt", f"{self.what}: {len(self.data) - self.pos} stream bytes were never read")

    # ---- 7.3 binarizations ----
    def flag(self, ctx):
        return self.bit(ctx)

    def tree(self, t):
        m = 1
        for _ in range(t.bits):
            m = 2 * m + self.bit(t.node(m))
        return m - (1 << t.bits)

    def uint(self, u):
        k = 0
        while k < 32 and self.bit(u.prefix[k]) == 1:
            k += 1
        v = 1
        for _ in range(k):
            v = (v << 1) | self.direct()
        return v - 1

    def sint(self, s):
        if self.flag(s.zero) == 0:
            return 0
        negative = self.flag(s.sign)
        magnitude = self.uint(s.mag) + 1
        return -magnitude if negative else magnitude

    def res8(self, r, allow_128=False):
        if self.flag(r.zero) == 0:
            return 0
        negative = self.flag(r.sign)
        k = self.tree(r.cls)
        magnitude = 1
        for _ in range(k):
            magnitude = (magnitude << 1) | self.direct()
        v = -magnitude if negative else magnitude
        if v == 128 and not allow_128:
            fail("Corrupt", f"{self.what}: a residual of +128")
        return v


def bits(n):
    """bits(n): the number of bits of n (bits(0) = 0)."""
    return n.bit_length()
