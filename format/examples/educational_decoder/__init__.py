"""The educational decoder's modules, one section of format/SPEC.md each:

errors.py       error classes (9.5) and little-endian fields (1)
container.py    signature, chunks, HEAD, TMPL, scanning for frames (2, 3, 9.3)
templates.py    range-coded bitmap samples (7.6)
strokes.py      the stroke model, stored records, the live list and motion (4, 5, 6)
stored.py       coding 0 bodies (6)
range_coder.py  the range decoder and binarizations (7.2, 7.3)
ranged.py       coding 1 bodies: prefix, edit stream, stroke stream (7.1, 7.4, 7.5)
polygon.py      the coding-1 polygon syntax (7.4 step 5)
replay.py       coding 2 bodies: generator, domain, canvas predictions (7.7)
render.py       coverage and compositing (8)
decoder.py      frames applied one after another (3.5, 5)
"""
