#!/usr/bin/env python3
"""Writes the synthetic Lottie files of this folder, one per feature group the importer holds
(tests/web/lottie_test.mjs compares each with lottie-web; tests/importers/lottie_test.cpp checks
their strokes). Run it here to regenerate them: python3 make_synthetic.py"""
import json


def st(v):
    return {"a": 0, "k": v}


def kf(frames, easing=((0.42, 0), (0.58, 1))):
    """Keyframes [(t, value), ...] with one easing; a value of None after a tuple marks hold."""
    out = []
    for k, (t, v, *hold) in enumerate(frames):
        e = {"t": t, "s": v if isinstance(v, list) else [v]}
        if k + 1 < len(frames):
            e["o"] = {"x": [easing[0][0]], "y": [easing[0][1]]}
            e["i"] = {"x": [easing[1][0]], "y": [easing[1][1]]}
        if hold:
            e["h"] = 1
        out.append(e)
    return {"a": 1, "k": out}


def tr(p=(0, 0), a=(0, 0), s=(100, 100), r=0, o=100):
    return {"ty": "tr", "p": st(list(p)), "a": st(list(a)), "s": st(list(s)), "r": st(r), "o": st(o)}


def ks(p=(0, 0), a=(0, 0), s=(100, 100), r=0, o=100):
    return {"p": p if isinstance(p, dict) else st(list(p)), "a": st(list(a)), "s": s if isinstance(s, dict) else st(list(s)),
            "r": r if isinstance(r, dict) else st(r), "o": o if isinstance(o, dict) else st(o)}


def fill(c, o=100):
    return {"ty": "fl", "c": st(list(c) + [1]), "o": st(o), "r": 1}


def stroke(c, w, lc=2, lj=2, o=100):
    return {"ty": "st", "c": st(list(c) + [1]), "o": st(o), "w": st(w), "lc": lc, "lj": lj, "ml": 4}


def shape_layer(ind, shapes, ip=0, op=60, **kw):
    layer = {"ddd": 0, "ind": ind, "ty": 4, "nm": f"layer {ind}", "ks": ks(**{k: v for k, v in kw.items() if k != "parent"}),
             "shapes": shapes, "ip": ip, "op": op, "st": 0, "sr": 1}
    if "parent" in kw:
        layer["parent"] = kw["parent"]
    return layer


def comp(layers, w=200, h=160, op=60, assets=()):
    return {"v": "5.7.0", "fr": 30, "ip": 0, "op": op, "w": w, "h": h, "nm": "synthetic", "ddd": 0,
            "assets": list(assets), "layers": layers}


def path(verts, ins, outs, closed=True):
    return {"ty": "sh", "ks": st({"v": verts, "i": ins, "o": outs, "c": closed})}


RED, GREEN, BLUE, YELLOW, DARK = (0.9, 0.1, 0.1), (0.1, 0.7, 0.2), (0.1, 0.3, 0.9), (0.95, 0.8, 0.1), (0.1, 0.1, 0.15)

files = {}
# Shapes: rectangle (rounded), ellipse, star, polygon, a Bezier path with a hole, fill opacity.
files["shapes.json"] = comp([
    shape_layer(1, [{"ty": "gr", "it": [
        {"ty": "rc", "p": st([50, 40]), "s": st([70, 50]), "r": st(12)}, fill(RED), tr()]},
        {"ty": "gr", "it": [{"ty": "el", "p": st([140, 45]), "s": st([80, 50])}, fill(BLUE, 60), tr()]},
        {"ty": "gr", "it": [{"ty": "sr", "sy": 1, "p": st([50, 115]), "pt": st(5), "or": st(35), "ir": st(15), "r": st(10),
                             "os": st(0), "is": st(0)}, fill(YELLOW), tr()]},
        {"ty": "gr", "it": [{"ty": "sr", "sy": 2, "p": st([105, 115]), "pt": st(6), "or": st(25), "r": st(0), "os": st(0)},
                            fill(GREEN), tr()]},
        {"ty": "gr", "it": [
            path([[150, 85], [190, 120], [150, 155], [110, 120]], [[-20, 0], [0, -20], [20, 0], [0, 20]],
                 [[20, 0], [0, 20], [-20, 0], [0, -20]]),
            path([[150, 105], [135, 120], [150, 135], [165, 120]], [[0, 0]] * 4, [[0, 0]] * 4),
            fill(DARK), tr()]}])], op=2)
# Strokes: caps and joins, on an open zigzag and a closed triangle, under a scaled group.
zig = lambda y: path([[20, y], [60, y - 25], [100, y], [140, y - 25], [180, y]], [[0, 0]] * 5, [[0, 0]] * 5, closed=False)
files["strokes.json"] = comp([
    shape_layer(1, [{"ty": "gr", "it": [zig(40), stroke(RED, 8, lc=1, lj=1)]},
                    {"ty": "gr", "it": [zig(85), stroke(BLUE, 8, lc=2, lj=2)]},
                    {"ty": "gr", "it": [zig(130), stroke(GREEN, 8, lc=3, lj=3)]},
                    {"ty": "gr", "it": [{"ty": "el", "p": st([0, 0]), "s": st([30, 30])}, stroke(DARK, 3, lc=1, lj=1),
                                        fill(YELLOW), tr(p=(170, 140), s=(150, 150))]}])], op=2)
# Animation: eased position, rotation and scale keyframes, a hold keyframe, a spatial tangent,
# parenting, an animated group transform and opacity.
files["animation.json"] = comp([
    shape_layer(2, [{"ty": "gr", "it": [{"ty": "rc", "p": st([0, 0]), "s": st([24, 24]), "r": st(0)}, fill(BLUE), tr(o=70)]}],
                parent=1, p=(40, 0), r=kf([(0, 0), (40, 180)])),
    # (Group opacity on the layer whose opacity is animated: lottie-web's canvas renderer then
    # draws the group's opacity alone, the spec multiplies them; so the group opacity is on layer 2.)
    shape_layer(1, [{"ty": "gr", "it": [{"ty": "el", "p": st([0, 0]), "s": st([30, 30])}, fill(RED), tr()]}],
                p={"a": 1, "k": [{"t": 0, "s": [40, 80], "o": {"x": 0.3, "y": 0}, "i": {"x": 0.7, "y": 1},
                                  "to": [30, -40], "ti": [-30, -40]}, {"t": 50, "s": [160, 80]}]},
                s=kf([(0, [60, 60]), (30, [130, 130]), (50, [100, 100])]),
                o=kf([(0, 100), (20, 40, "hold"), (45, 100)]))], op=60)
# Precomps: a precomp placed twice, one late (start time) and one time-remapped; a solid layer.
inner = [shape_layer(1, [{"ty": "gr", "it": [{"ty": "sr", "sy": 1, "p": st([0, 0]), "pt": st(4), "or": st(30), "ir": st(12),
                                              "r": st(0), "os": st(0), "is": st(0)}, fill(YELLOW), tr()]}],
                     p=(40, 40), r=kf([(0, 0), (60, 90)]), op=120)]
files["precomp.json"] = comp([
    {"ddd": 0, "ind": 1, "ty": 0, "refId": "star", "ks": ks(p=(0, 20)), "w": 80, "h": 80, "ip": 0, "op": 60, "st": 0, "sr": 1},
    {"ddd": 0, "ind": 2, "ty": 0, "refId": "star", "ks": ks(p=(110, 20)), "w": 80, "h": 80, "ip": 10, "op": 60, "st": 10, "sr": 1},
    {"ddd": 0, "ind": 3, "ty": 0, "refId": "star", "ks": ks(p=(60, 80)), "w": 80, "h": 80, "ip": 0, "op": 60, "st": 0, "sr": 1,
     "tm": kf([(0, 1.0), (59, 0.0)], easing=((0, 0), (1, 1)))},
    {"ddd": 0, "ind": 4, "ty": 1, "sc": "#33aa88", "sw": 200, "sh": 40, "ks": ks(p=(0, 120)), "ip": 0, "op": 60, "st": 0, "sr": 1},
], op=60, assets=[{"id": "star", "layers": inner}])
# Trim paths: an animated trim of a stroked circle and of two paths trimmed as one.
files["trim.json"] = comp([
    shape_layer(1, [{"ty": "gr", "it": [{"ty": "el", "p": st([60, 80]), "s": st([80, 80])},
                                        {"ty": "tm", "s": st(0), "e": kf([(0, 0), (40, 100)]), "o": st(45), "m": 1},
                                        stroke(RED, 10, lc=2, lj=2), tr()]},
                    {"ty": "gr", "it": [zig(60), zig(120),
                                        {"ty": "tm", "s": kf([(0, 0), (40, 50)]), "e": st(100), "o": st(0), "m": 2},
                                        stroke(BLUE, 6, lc=1, lj=1), tr(p=(0, 0), s=(100, 100))]}])], op=45)
# Dashes: a dashed circle (round caps) with an animated offset, a dashed zigzag (butt caps).
dashed = lambda st_, pattern, off: dict(st_, d=[{"n": "d", "v": st(pattern[0])}, {"n": "g", "v": st(pattern[1])},
                                                {"n": "o", "v": off}])
files["dashes.json"] = comp([
    shape_layer(1, [{"ty": "gr", "it": [{"ty": "el", "p": st([60, 80]), "s": st([80, 80])},
                                        dashed(stroke(RED, 6, lc=2, lj=2), (14, 8), kf([(0, 0), (30, 44)])), tr()]},
                    {"ty": "gr", "it": [zig(60), dashed(stroke(BLUE, 5, lc=1, lj=1), (20, 6), st(5)), tr(p=(0, 80))]}])], op=30)
for name, doc in files.items():
    with open(name, "w") as f:
        json.dump(doc, f, separators=(",", ":"))
        f.write("\n")

# The shapes as a .lottie archive (dotLottie: manifest.json and animations/<id>.json).
import zipfile
with zipfile.ZipFile("shapes.lottie", "w", zipfile.ZIP_DEFLATED) as z:
    z.writestr("manifest.json", json.dumps({"version": "1", "animations": [{"id": "shapes"}]}))
    z.writestr("animations/shapes.json", json.dumps(files["shapes.json"], separators=(",", ":")))
