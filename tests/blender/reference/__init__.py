"""The oracle of the add-on's file layer: the plain, one-tuple-per-stroke versions of what the
add-on ships vectorised (geometry, record parsing, live-list update, record packing and frame
coding). They live with the tests: Blender only ever runs the numpy paths, and test_io.py checks
that both give the same strokes, lists and bytes."""
