"""spt paint's option table, as the add-on offers it: the options the panel shows, their
property names, and the `spt paint` arguments for the panel's values.

The table is spt's own (`spt paint --options-json`, converter/src/job/option_table.cpp); it ships
with the add-on as paint_options.json, written by the spt the add-on was built with, and a test
keeps the two equal. No bpy here: the panel (blender/panel.py) builds its properties from these
rows, and the subprocess layer (spt_tool.py) its arguments."""

import json
import os

TABLE = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "paint_options.json")
_ACRONYMS = {"psnr": "PSNR", "roi": "ROI", "fps": "FPS"}


def load(path: str = TABLE) -> list:
    """The table's rows (dicts: name, kind, default, min, max, choices, help, styles, scope, addon)."""
    with open(path, encoding="utf-8") as f:
        doc = json.load(f)
    if doc.get("format") != "spt-paint-options" or not isinstance(doc.get("options"), list):
        raise ValueError(f"{path}: not an spt paint option table")
    return doc["options"]


def panel_rows(rows: list) -> list:
    """The rows the panel shows, in spt's --help order."""
    return [r for r in rows if r.get("addon")]


def prop_name(row: dict) -> str:
    """The Blender property of an option: --max-strokes is max_strokes."""
    return row["name"].replace("-", "_")


def label(row: dict) -> str:
    words = [_ACRONYMS.get(w, w) for w in row["name"].split("-")]
    words[0] = words[0][:1].upper() + words[0][1:]
    return " ".join(words)


def enum_id(choice: str) -> str:
    """An enum item's identifier for a choice ("painterly" -> "PAINTERLY")."""
    return choice.upper().replace("-", "_")


def is_number_text(row: dict) -> bool:
    """A text option whose default is a whole number (--seed) is a number in the panel."""
    return row["kind"] == "text" and str(row.get("default", "")).isdigit()


def applies(row: dict, style: str) -> bool:
    """Whether the option shapes a painting in `style` (the panel greys out the others)."""
    return style in row.get("styles", [style])


def paint_args(rows: list, values: dict) -> list:
    """`spt paint` arguments for `values` (property name -> value; a choice as its enum identifier
    or its own text). Left out: unset values (None, "", and 0 for numbers: spt's default), a
    choice at its default, options that are not about the painting (run and planning options),
    and options the chosen style does not take (spt would refuse them)."""
    style = str(values.get("style", "painterly")).lower()
    args = []
    for r in rows:
        if r.get("scope") in ("run", "planning"):
            continue
        v = values.get(prop_name(r))
        if v is None or v == "" or not applies(r, style):
            continue
        opt = "--" + r["name"]
        kind = r["kind"]
        if kind == "flag":
            if v:
                args.append(opt)
            continue
        if kind in ("integer", "number") and v == 0:
            continue
        if kind == "choice":
            v = next((c for c in r["choices"] if enum_id(c) == str(v) or c == str(v)), str(v))
            if v == r.get("default"):
                continue
        args += [opt, f"{v:g}" if isinstance(v, float) else str(v)]
    return args
