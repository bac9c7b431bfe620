"""Running the `spt` executable: finding it, checking its version, pack and paint.

No bpy here (importable and testable without Blender, like io/): operators call these and
turn SptToolError into a Blender error report."""

import json
import os
import re
import shutil
import subprocess
import tempfile
import threading

from .io import paint_options

MIN_VERSION = (0, 1, 0)


class SptToolError(Exception):
    pass


def default_path() -> str:
    """`spt` next to the add-on (a bundled build), else the one on PATH, else ''."""
    here = os.path.dirname(os.path.abspath(__file__))
    for cand in (os.path.join(here, "bin", "spt"), os.path.join(here, "spt")):
        if os.path.isfile(cand) and os.access(cand, os.X_OK):
            return cand
    return shutil.which("spt") or ""


def resolve(path: str) -> str:
    """The executable to run; raises SptToolError with a clear message when it is unusable."""
    exe = path or default_path()
    if not exe:
        raise SptToolError("the 'spt' tool was not found: install it on PATH or set its path in "
                           "Preferences > Add-ons > spt Grease Pencil")
    if os.sep in exe or (os.altsep and os.altsep in exe):
        if not os.path.isfile(exe):
            raise SptToolError(f"the 'spt' tool was not found at {exe} (check the add-on preferences)")
    else:
        found = shutil.which(exe)
        if not found:
            raise SptToolError(f"the 'spt' tool '{exe}' is not on PATH (check the add-on preferences)")
        exe = found
    return exe


def version(path: str):
    """(major, minor, patch) reported by `spt --version`; raises SptToolError."""
    exe = resolve(path)
    try:
        r = subprocess.run([exe, "--version"], capture_output=True, text=True, timeout=20)
    except (OSError, subprocess.TimeoutExpired) as e:
        raise SptToolError(f"cannot run {exe}: {e}") from None
    m = re.search(r"(\d+)\.(\d+)\.(\d+)", r.stdout)
    if r.returncode != 0 or not m:
        raise SptToolError(f"{exe} --version failed: {(r.stderr or r.stdout).strip()[:300]}")
    v = tuple(int(g) for g in m.groups())
    if v < MIN_VERSION:
        raise SptToolError(f"{exe} is version {'.'.join(map(str, v))}; this add-on needs "
                           f"{'.'.join(map(str, MIN_VERSION))} or newer")
    return v


def _tail(text: str, n: int = 600) -> str:
    text = (text or "").strip()
    return text[-n:]


def pack_stored(spt_path: str, src: str, dst: str) -> None:
    """`spt pack SRC --stored -o DST`."""
    exe = resolve(spt_path)
    try:
        r = subprocess.run([exe, "pack", src, "--stored", "-o", dst], capture_output=True, text=True)
    except OSError as e:
        raise SptToolError(f"cannot run {exe}: {e}") from None
    if r.returncode != 0:
        raise SptToolError(f"spt pack failed on {src}: {_tail(r.stderr or r.stdout)}")


def pack_coded(spt_path: str, src: str, dst: str) -> None:
    """`spt pack SRC -o DST` (stored -> range-coded)."""
    exe = resolve(spt_path)
    try:
        r = subprocess.run([exe, "pack", src, "-o", dst], capture_output=True, text=True)
    except OSError as e:
        raise SptToolError(f"cannot run {exe}: {e}") from None
    if r.returncode != 0:
        raise SptToolError(f"spt pack failed on {src}: {_tail(r.stderr or r.stdout)}")


def temp_path(suffix=".spt") -> str:
    fd, p = tempfile.mkstemp(prefix="spt-blender-", suffix=suffix)
    os.close(fd)
    return p


def paint_args(opts: dict) -> list:
    """Command-line options of `spt paint` from the panel's settings (property name -> value),
    through spt's option table (io/paint_options.py): defaults and options the style does not
    take are left out."""
    return paint_options.paint_args(paint_options.load(), opts)


class PaintJob:
    """`spt paint INPUT -o TMP ... --progress json` in the background.

    spt writes to a private file beside OUTPUT (TMP), renamed to OUTPUT only when the paint
    succeeds: a cancelled or failed paint leaves no output and never touches an existing OUTPUT.
    A reader thread parses the JSON lines of stdout into `percent`, `done`, `total`; the caller
    polls (a modal timer) or calls wait(). cancel() asks spt to stop (SIGTERM: a video paint
    then finishes its current frame and writes what it has), kills it when it does not end
    within `grace` seconds, and removes TMP and spt's own TMP.partial."""

    def __init__(self, spt_path: str, source: str, output: str, opts: dict, grace: float = 3.0):
        self.exe = resolve(spt_path)
        self.output = output
        folder, base = os.path.split(os.path.abspath(output))
        self.work = os.path.join(folder, f".{base}.painting-{os.getpid()}-{id(self):x}.spt")
        self.grace = grace
        self.cmd = [self.exe, "paint", source, "-o", self.work] + paint_args(opts) + ["--progress", "json"]
        self.percent = 0.0
        self.done = 0.0
        self.total = 0.0
        self.ended = False
        self.end_event = None
        self.cancelled = False
        self._stderr = []
        try:
            self.proc = subprocess.Popen(self.cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                         stdin=subprocess.DEVNULL, text=True, bufsize=1)
        except OSError as e:
            raise SptToolError(f"cannot run {self.exe}: {e}") from None
        self._out = threading.Thread(target=self._read_stdout, daemon=True)
        self._err = threading.Thread(target=self._read_stderr, daemon=True)
        self._out.start()
        self._err.start()

    def _read_stdout(self):
        for line in self.proc.stdout:
            line = line.strip()
            if not line.startswith("{"):
                continue
            try:
                ev = json.loads(line)
            except ValueError:
                continue
            if ev.get("event") == "progress":
                self.done = float(ev.get("done", 0) or 0)
                self.total = float(ev.get("total", 0) or 0)
                pct = ev.get("percent")
                if pct is None and self.total > 0:
                    pct = 100.0 * self.done / self.total
                self.percent = max(0.0, min(100.0, float(pct or 0)))
            elif ev.get("event") == "end":
                self.end_event = ev
                self.percent = 100.0 if ev.get("ok", True) else self.percent

    def _read_stderr(self):
        for line in self.proc.stderr:
            self._stderr.append(line)
            del self._stderr[:-50]  # keep the tail only

    def poll(self):
        """None while running, else the exit code."""
        return self.proc.poll()

    def cancel(self):
        """Stops spt and removes everything it wrote; returns when the process has ended."""
        self.cancelled = True
        if self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(timeout=self.grace)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
        self._join()
        self._remove_work()

    def _remove_work(self):
        for p in (self.work, self.work + ".partial"):
            try:
                os.unlink(p)
            except OSError:
                pass

    def _join(self):
        self._out.join(timeout=5)
        self._err.join(timeout=5)

    def wait(self):
        """Blocks until the process ends (the background/test path), then moves the painting to
        OUTPUT; raises SptToolError (and removes spt's files) when it failed."""
        self.proc.wait()
        self._join()
        try:
            self.check()
            os.replace(self.work, self.output)
        except OSError as e:
            self._remove_work()
            raise SptToolError(f"cannot write {self.output}: {e.strerror or e}") from None
        except SptToolError:
            self._remove_work()
            raise

    def check(self):
        code = self.proc.returncode
        if code != 0:
            raise SptToolError(f"spt paint failed (exit {code}): {_tail(''.join(self._stderr))}")
        if not os.path.isfile(self.work):
            raise SptToolError(f"spt paint wrote no file at {self.work}")
