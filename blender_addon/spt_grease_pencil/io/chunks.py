"""Chunk framing of format/SPEC.md section 2: signature, length, type, payload, CRC-32."""

import struct
import zlib

SIGNATURE = b"\x89SPT\r\n\x1a\n"
_LEN_TYPE = struct.Struct("<I4s")
_CRC = struct.Struct("<I")


def chunk_bytes(ctype: bytes, payload: bytes) -> bytes:
    """One framed chunk: u32 length, type, payload, CRC over type and payload."""
    crc = zlib.crc32(payload, zlib.crc32(ctype)) & 0xFFFFFFFF
    return _LEN_TYPE.pack(len(payload), ctype) + payload + _CRC.pack(crc)


def valid_type(ctype: bytes) -> bool:
    return len(ctype) == 4 and all((65 <= c <= 90) or (97 <= c <= 122) or c == 32 for c in ctype[1:]) \
        and ((65 <= ctype[0] <= 90) or (97 <= ctype[0] <= 122))


def is_critical(ctype: bytes) -> bool:
    return 65 <= ctype[0] <= 90


def scan(data, max_chunk_bytes: int):
    """Yields (offset, type, payload memoryview) for each complete, CRC-valid chunk.

    Stops (returning a reason string through StopIteration's value) at the first chunk that is
    truncated or fails its CRC, which is what recovery (section 3.7) needs."""
    mv = memoryview(data)
    n = len(data)
    pos = len(SIGNATURE)
    while pos < n:
        if n - pos < 12:
            return f"truncated chunk header at byte {pos}"
        length, ctype = _LEN_TYPE.unpack_from(mv, pos)
        if not valid_type(ctype):
            return f"invalid chunk type {ctype!r} at byte {pos}"
        if length > max_chunk_bytes:
            return f"chunk {ctype.decode('latin-1')} at byte {pos}: length {length} exceeds the limit {max_chunk_bytes}"
        if length > n - pos - 12:
            return f"chunk {ctype.decode('latin-1')} at byte {pos}: length {length} runs past the end of the file ({n} bytes)"
        payload = mv[pos + 8:pos + 8 + length]
        (crc,) = _CRC.unpack_from(mv, pos + 8 + length)
        if zlib.crc32(payload, zlib.crc32(ctype)) & 0xFFFFFFFF != crc:
            return f"chunk {ctype.decode('latin-1')} at byte {pos}: CRC mismatch"
        yield pos, ctype, payload
        pos += 12 + length
    return None
