"""What import_bench.py and import_bound.py share: their command line (the spt binary and the
media folder whose foreign/ holds the other painters' samples), xz sizes and entropies."""
import argparse, collections, lzma, math, os

def parse_args(doc):
    """--spt and --media, defaults relative to bench/; returns (args, foreign folder)."""
    here = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")  # bench/
    ap = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--spt", default=os.path.join(here, "..", "build", "bin", "spt"))
    ap.add_argument("--media", default=os.path.join(here, "..", "..", "shared", "media"))
    a = ap.parse_args()
    return a, os.path.join(a.media, "foreign")

def xz_bytes(path):
    """Size of the file compressed with xz -9e."""
    with open(path, "rb") as f:
        return len(lzma.compress(f.read(), preset=9 | lzma.PRESET_EXTREME))

def entropy_bits(values):
    """Empirical order-0 entropy of a list of values, in bits (the whole list, not per value)."""
    n = len(values)
    return -sum(c * math.log2(c / n) for c in collections.Counter(values).values()) if n else 0.0
