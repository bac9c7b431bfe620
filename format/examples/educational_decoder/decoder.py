"""Frames (SPEC.md 3.5) applied to the live stroke list (SPEC.md 5), frame by frame."""
from .container import open_spt
from .errors import ByteReader, fail
from .ranged import decode_ranged
from .replay import decode_replay
from .stored import decode_stored
from .strokes import check_stroke, remove_and_move


class decode_frames:
    """Iterating yields (frame_index, live list) for every frame of an .spt file, in order.
    `header` and `templates` are the file's; `problem` says why a file is incomplete."""

    def __init__(self, data):
        spt = open_spt(data)
        self.header, self.templates, self.problem = spt.header, spt.templates, spt.problem
        self.frames = spt.frames

    def __iter__(self):
        header, templates = self.header, self.templates
        live = []
        for index, payload in enumerate(self.frames):
            what = f"frame {index}"
            r = ByteReader(payload, what)
            r.u32("frame_index")  # checked by open_spt
            frame_type, coding = r.u8("frame_type"), r.u8("coding")
            if r.u16("reserved") != 0:
                fail("Unsupported", f"{what}: reserved field is not 0")
            if frame_type > 1:
                fail("Unsupported", f"{what}: frame type {frame_type} is reserved")
            key = frame_type == 0
            if index == 0 and not key:
                fail("Corrupt", "the first frame is not a key frame")
            body = payload[8:]
            if coding == 0:
                removed, motion, added = decode_stored(body, key, header, what)
            elif coding == 1:
                removed, motion, added = decode_ranged(body, key, header, len(templates), len(live), what)
            elif coding == 2:
                removed, motion, added = decode_replay(body, key, header, templates, live, what)
            else:
                fail("Unsupported", f"{what}: frame coding {coding} is reserved")
            for s in added:
                check_stroke(s, header, len(templates), what)
            live = added if key else remove_and_move(live, removed, motion, what) + added
            if len(live) > 1 << 24:
                fail("LimitExceeded", f"{what}: {len(live)} live strokes")
            yield index, live
