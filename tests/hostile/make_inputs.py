#!/usr/bin/env python3
"""Writes the crafted inputs of hostile_cli_test.cpp into inputs/ (run from this folder; the
outputs are committed). Images are made here byte by byte; .spt files are golden files with one
field changed (CRC fixed where the field is covered by it)."""
import os, struct, subprocess, zlib

G = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'format', 'golden')
OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'inputs')

def png_chunk(t, data):
    return struct.pack('>I', len(data)) + t + data + struct.pack('>I', zlib.crc32(t + data))

def png(w, h, rows=None):
    raw = rows if rows is not None else b''.join(b'\0' + bytes((x * 7 + y * 3) % 256 for x in range(w * 3)) for y in range(h))
    return (b'\x89PNG\r\n\x1a\n' + png_chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 2, 0, 0, 0)) +
            png_chunk(b'IDAT', zlib.compress(raw)) + png_chunk(b'IEND', b''))

def spt_chunks(d):
    p, out = 8, []
    while p + 8 <= len(d):
        n, = struct.unpack('<I', d[p:p + 4])
        out.append((p, d[p + 4:p + 8], n))
        p += 12 + n
    return out

def write(name, data):
    with open(os.path.join(OUT, name), 'wb') as f:
        f.write(data)

os.makedirs(OUT, exist_ok=True)
good = png(16, 12)
write('good.png', good)
write('truncated.png', good[:len(good) // 2])                   # cut inside IDAT
write('empty.png', b'')
write('not_an_image.png', b'this is a text file, not a PNG\n')
# IHDR says 1,000,000 x 1,000,000 (CRC fixed): the pixel limit, not a 3 TB allocation.
write('lying_size.png', good[:16] + struct.pack('>II', 1000000, 1000000) + good[24:29] +
      struct.pack('>I', zlib.crc32(good[12:16] + struct.pack('>II', 1000000, 1000000) + good[24:29])) + good[33:])
# IHDR says 16 x 4000 but IDAT holds 12 rows.
tall = good[:16] + struct.pack('>II', 16, 4000) + good[24:29]
write('lying_rows.png', tall + struct.pack('>I', zlib.crc32(tall[12:29])) + good[33:])

im = open(os.path.join(G, 'inter_motion.spt'), 'rb').read()
fr = [c for c in spt_chunks(im) if c[1] == b'FRAM']
# Issue 20 item 4: the second FRAM claims 0xFFFFFFFF bytes (the length is outside the CRC).
d = bytearray(im)
struct.pack_into('<I', d, fr[1][0], 0xFFFFFFFF)
write('frame1_length_ffffffff.spt', bytes(d))
# A valid file with a copy of itself appended.
write('appended_copy.spt', im + im)
# A huge added_count varint (2^27) in frame 0 of a range-coded file, CRC fixed.
d = bytearray(im)
p, t, n = fr[0]
d[p + 16:p + 20] = b'\x80\x80\x80\x40'
struct.pack_into('<I', d, p + 8 + n, zlib.crc32(bytes(d[p + 4:p + 8 + n])))
write('huge_stroke_count.spt', bytes(d))
# HEAD claims a 2^31 x 2^31 canvas, CRC fixed.
d = bytearray(im)
hp, ht, hn = spt_chunks(im)[0]
struct.pack_into('<II', d, hp + 8 + 8, 0x80000000, 0x80000000)
struct.pack_into('<I', d, hp + 8 + hn, zlib.crc32(bytes(d[hp + 4:hp + 8 + hn])))
write('head_huge_canvas.spt', bytes(d))
# Truncated in the middle of frame 2 (a crashed writer).
write('truncated.spt', im[:fr[2][0] + 10])
# A chunk length pointing past the end of the file in the header chunks.
d = bytearray(im)
struct.pack_into('<I', d, spt_chunks(im)[1][0], 0x7FFFFFF0)
write('tmpl_length_past_end.spt', bytes(d))
# A metadata value that is not UTF-8 (from a writer that did not check), CRC fixed.
ni = bytearray(open(os.path.join(G, 'no_index.spt'), 'rb').read())
mp, mt, mn = [c for c in spt_chunks(ni) if c[1] == b'meta'][0]
ni[mp + 8 + mn - 1] = 0xFF
struct.pack_into('<I', ni, mp + 8 + mn, zlib.crc32(bytes(ni[mp + 4:mp + 8 + mn])))
write('meta_not_utf8.spt', bytes(ni))
write('svg_1e93.svg', b'<svg xmlns="http://www.w3.org/2000/svg" width="1e93" height="10"></svg>')
write('strokes_bad_utf8.json', b'{"format": "spt-strokes", "version": 1, "canvas": {"width": 8, "height": 8}, '
      b'"metadata": {"title": "caf\xe9"}, "frames": [{"type": "key", "strokes": []}]}')
write('strokes_min.json', b'{"format": "spt-strokes", "version": 1, "canvas": {"width": 8, "height": 8}, '
      b'"frames": [{"type": "key", "strokes": []}]}')
# A video whose header promises 30 frames, cut to half its bytes (a copy that stopped early):
# the AVI index at the end is gone, and decoding ends after frame 0. ffmpeg's test pattern,
# MPEG-4 part 2; the whole file too, which must decode all 30.
whole = os.path.join(OUT, 'video_30f.avi')
subprocess.run(['ffmpeg', '-v', 'error', '-y', '-f', 'lavfi', '-i', 'testsrc=size=64x48:rate=24', '-frames:v', '30',
                '-c:v', 'mpeg4', '-q:v', '5', '-g', '10', '-fflags', '+bitexact', '-flags', '+bitexact', whole],
               check=True)
v = open(whole, 'rb').read()
write('video_30f_cut.avi', v[:len(v) // 2])
