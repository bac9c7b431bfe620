"""StreamInfo <-> JSON text, kept on the Grease Pencil data so export can write the same header,
templates, metadata and regions of interest the file was imported with."""

import base64
import json

from .model import Header, Roi, StreamInfo, Template


def to_json(info: StreamInfo) -> str:
    h = info.header
    return json.dumps({
        "header": {"width": h.width, "height": h.height, "fps": [h.fps_num, h.fps_den],
                   "background": list(h.background), "sets": [list(s) for s in h.sets],
                   "orientations": [list(o) for o in h.orientations],
                   "alpha": bool(h.alpha), "color_encoding": int(h.color_encoding),
                   "background_lo": list(h.background_lo), "curve_grid": bool(h.curve_grid)},
        "templates": [{"kind": t.kind, "width": t.width, "height": t.height, "name": t.name,
                       "pixels": base64.b64encode(t.pixels).decode("ascii"), "supersample": t.supersample} for t in info.templates],
        "metadata": [list(kv) for kv in info.metadata],
        "rois": [[r.first_frame, r.last_frame, r.x, r.y, r.w, r.h] for r in info.rois],
        "extra": [[c.decode("latin-1"), base64.b64encode(p).decode("ascii")] for c, p in info.extra_chunks],
    }, separators=(",", ":"))


def from_json(text: str) -> StreamInfo:
    d = json.loads(text)
    hd = d["header"]
    h = Header(width=int(hd["width"]), height=int(hd["height"]), fps_num=int(hd["fps"][0]),
               fps_den=int(hd["fps"][1]), background=tuple(int(v) for v in hd["background"]),
               sets=[tuple(int(v) for v in s) for s in hd["sets"]],
               orientations=[tuple(int(v) for v in o) for o in hd["orientations"]],
               alpha=bool(hd.get("alpha", False)), color_encoding=int(hd.get("color_encoding", 0)),
               background_lo=tuple(int(v) for v in hd.get("background_lo", (0, 0, 0))),
               curve_grid=bool(hd.get("curve_grid", False)))
    info = StreamInfo(header=h)
    info.templates = [Template(int(t["kind"]), int(t["width"]), int(t["height"]),
                               base64.b64decode(t["pixels"]), t.get("name", ""), int(t.get("supersample", 0))) for t in d.get("templates", [])]
    info.metadata = [(k, v) for k, v in d.get("metadata", [])]
    info.rois = [Roi(*map(int, r)) for r in d.get("rois", [])]
    info.extra_chunks = [(c.encode("latin-1"), base64.b64decode(p)) for c, p in d.get("extra", [])]
    return info
