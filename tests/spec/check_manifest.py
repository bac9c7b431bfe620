#!/usr/bin/env python3
"""Runs format/examples/educational_decoder.py on every golden file that
tests/format/golden/MANIFEST.txt lists and compares its lines with the manifest's.

    check_manifest.py DECODER MANIFEST [--render]

Without --render it compares `frame live_strokes live_fnv1a64`; with --render the decoder also
renders every frame and `render_fnv1a64` is compared too. Exits 1 on any difference, and when
the decoder reports a problem (every golden file is complete and valid)."""
import os
import subprocess
import sys


def main(argv):
    decoder, manifest = argv[1], argv[2]
    with_render = "--render" in argv[3:]
    expected = {}
    for line in open(manifest, encoding="utf-8"):
        if line.startswith("#") or not line.strip():
            continue
        name, *fields = line.split()
        if len(fields) != 4:
            print(f"{manifest}: malformed line: {line.rstrip()}")
            return 1
        expected.setdefault(name, []).append(" ".join(fields if with_render else fields[:3]))
    if not expected:
        print(f"{manifest}: lists no files")
        return 1
    folder = os.path.dirname(os.path.abspath(manifest))
    failures = 0
    for name, lines in expected.items():
        cmd = [sys.executable, decoder] + (["--render"] if with_render else []) + [os.path.join(folder, name)]
        run = subprocess.run(cmd, capture_output=True, text=True)
        got = run.stdout.splitlines()
        # Golden files are complete and valid: any message on stderr is a failure too.
        if run.returncode != 0 or got != lines or run.stderr:
            failures += 1
            print(f"FAIL {name} (exit {run.returncode})")
            for i in range(max(len(lines), len(got))):
                want = lines[i] if i < len(lines) else "(none)"
                have = got[i] if i < len(got) else "(none)"
                if want != have:
                    print(f"  manifest: {want}\n  decoder:  {have}")
            if run.stderr:
                print("  " + run.stderr.strip().replace("\n", "\n  "))
        else:
            print(f"ok   {name}: {len(lines)} frames")
    print(f"{len(expected) - failures} of {len(expected)} golden files decode as MANIFEST.txt says")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
