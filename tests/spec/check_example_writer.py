#!/usr/bin/env python3
"""The two examples of format/examples agree: what write_stored.py writes (SPEC.md 6), the
educational decoder reads back, frame by frame, with the strokes the writer put in.

    check_example_writer.py EXAMPLES_DIR WORK_DIR"""
import os
import subprocess
import sys


def main(argv):
    examples, work = argv[1], argv[2]
    out = os.path.join(work, "example_stored.spt")
    frames = 4
    subprocess.run([sys.executable, os.path.join(examples, "write_stored.py"), out, str(frames)], check=True)
    run = subprocess.run([sys.executable, os.path.join(examples, "educational_decoder.py"), "--render", out],
                         capture_output=True, text=True)
    lines = run.stdout.splitlines()
    print(run.stdout + run.stderr)
    if run.returncode != 0 or run.stderr:
        print("FAIL: the educational decoder does not read the example writer's file")
        return 1
    # write_stored.py writes 30, 60 and 90 stamps in its three sets, every frame a key frame.
    want = [f"{i} 180" for i in range(frames)]
    if [" ".join(line.split()[:2]) for line in lines] != want:
        print(f"FAIL: expected frames and stroke counts {want}")
        return 1
    if len({line.split()[3] for line in lines}) != frames:
        print("FAIL: the frames render alike, but the writer changes their colours")
        return 1
    print("ok: write_stored.py's file decodes as written")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
