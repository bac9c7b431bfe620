"""Helpers of the file-layer tests (standard library only): a file's bytes, a test case with a
temporary folder, and chunk CRCs made right again after a test damages a payload, so that the
payload parsers, not the CRC check, meet the damage."""

import os
import struct
import tempfile
import unittest
import zlib


def read_all(p):
    with open(p, "rb") as f:
        return f.read()


def fix_chunk_crc(d: bytearray, pos: int) -> int:
    """Rewrites the CRC of the chunk at byte `pos` of `d` (length, FourCC, payload, CRC); returns
    the payload length."""
    n = struct.unpack_from("<I", d, pos)[0]
    struct.pack_into("<I", d, pos + 8 + n, zlib.crc32(bytes(d[pos + 4:pos + 8 + n])) & 0xFFFFFFFF)
    return n


def fix_all_crcs(d: bytearray) -> bytearray:
    """Rewrites the CRC of every whole chunk after the signature, up to the first that does not fit."""
    pos = 8
    while pos + 12 <= len(d):
        n = struct.unpack_from("<I", d, pos)[0]
        if pos + 12 + n > len(d):
            break
        fix_chunk_crc(d, pos)
        pos += 12 + n
    return d


def damaged(data: bytes, rng) -> bytearray:
    """`data` with one to three random bytes after the signature changed, CRCs made right."""
    d = bytearray(data)
    for _k in range(rng.randrange(1, 4)):
        d[rng.randrange(8, len(d))] = rng.randrange(256)
    return fix_all_crcs(d)


class Tmp(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.dir.cleanup()

    def path(self, name):
        return os.path.join(self.dir.name, name)
