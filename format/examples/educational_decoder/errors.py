"""The error classes of SPEC.md 9.5, and a reader of little-endian bytes (SPEC.md 1)."""


class DecodeError(Exception):
    """A file this decoder rejects; `code` is one of the classes of SPEC.md 9.5."""

    def __init__(self, code, message):
        super().__init__(f"{code}: {message}")
        self.code = code


def fail(code, message):
    raise DecodeError(code, message)


class ByteReader:
    """Reads the fixed-size fields of SPEC.md from a bytes object, front to back."""

    def __init__(self, data, what):
        self.data = data
        self.pos = 0
        self.what = what  # names the chunk or body in error messages

    def left(self):
        return len(self.data) - self.pos

    def take(self, n, field):
        if n > self.left():
            fail("Truncated", f"{self.what}: {field} is cut off")
        b = self.data[self.pos:self.pos + n]
        self.pos += n
        return b

    def uint(self, n, field):
        return int.from_bytes(self.take(n, field), "little")

    def sint(self, n, field):
        return int.from_bytes(self.take(n, field), "little", signed=True)

    def u8(self, field):
        return self.uint(1, field)

    def u16(self, field):
        return self.uint(2, field)

    def u32(self, field):
        return self.uint(4, field)

    def u64(self, field):
        return self.uint(8, field)

    def i16(self, field):
        return self.sint(2, field)

    def i32(self, field):
        return self.sint(4, field)

    def varint(self, field):
        # SPEC.md 7.1: ULEB128, at most 5 bytes, fits 32 bits, shortest form.
        value = 0
        for i in range(5):
            b = self.u8(field)
            value |= (b & 0x7F) << (7 * i)
            if b & 0x80 == 0:
                if i > 0 and b == 0:
                    fail("Corrupt", f"{self.what}: {field} is not in its shortest form")
                if value >= 1 << 32:
                    fail("Corrupt", f"{self.what}: {field} does not fit 32 bits")
                return value
        fail("Corrupt", f"{self.what}: {field} is longer than 5 bytes")

    def end(self):
        if self.left():
            fail("Corrupt", f"{self.what}: {self.left()} bytes follow the last value")
