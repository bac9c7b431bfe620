// The JSON stroke list writer. Output is deterministic and exact: Q4 values are written as
// pixels with at most four decimals (k/16 has a finite decimal expansion), so importing the
// output gives back the same values, and the same .spt bytes.
#include <cstdio>

#include "spt_import/export.hpp"
#include "spt_import/codec.hpp"
#include "spt_json/json.hpp"

namespace spt::import {

namespace {

void q4(std::string& o, int64_t v) {
    if (v < 0) { o += '-'; v = -v; }
    o += std::to_string(v / 16);
    if (int64_t f = v % 16) {
        char buf[8];
        std::snprintf(buf, sizeof buf, "%04d", int(f * 625));
        std::string s(buf);
        while (s.back() == '0') s.pop_back();
        o += '.';
        o += s;
    }
}

// Colour encoding 1 (`linear`) writes the 16-bit half codes (exact); encoding 0 the 8-bit values.
void color(std::string& o, Rgba8 c, bool linear) {
    if (linear) {
        o += "\"color\": [" + std::to_string(code16(c, 0)) + ", " + std::to_string(code16(c, 1)) + ", " + std::to_string(code16(c, 2)) +
             ", " + std::to_string(c.a) + "]";
        return;
    }
    o += "\"color\": [" + std::to_string(c.r) + ", " + std::to_string(c.g) + ", " + std::to_string(c.b) + ", " + std::to_string(c.a) + "]";
}

void stroke(std::string& o, const Stroke& s, bool linear) {
    switch (s.kind) {
        case StrokeKind::Stamp: {
            const auto& t = s.stamp;
            o += "{\"type\": \"stamp\", \"set\": " + std::to_string(t.set) + ", \"template\": " + std::to_string(t.tmpl) +
                 ", \"orient\": " + std::to_string(t.orient) + ", \"x\": ";
            q4(o, t.x); o += ", \"y\": "; q4(o, t.y); o += ", ";
            color(o, t.color, linear);
            o += "}";
            break;
        }
        case StrokeKind::Affine: {
            const auto& a = s.affine;
            o += "{\"type\": \"affine\", \"template\": " + std::to_string(a.tmpl) + ", \"tx\": ";
            q4(o, a.tx); o += ", \"ty\": "; q4(o, a.ty);
            o += ", \"a\": "; q4(o, a.a); o += ", \"b\": "; q4(o, a.b);
            o += ", \"c\": "; q4(o, a.c); o += ", \"d\": "; q4(o, a.d); o += ", ";
            color(o, a.color, linear);
            o += "}";
            break;
        }
        case StrokeKind::Curve: {
            o += "{\"type\": \"curve\", ";
            color(o, s.curve.color, linear);
            if (s.curve.supersample) o += ", \"supersample\": " + std::to_string(s.curve.supersample);
            o += ", \"points\": [";
            for (size_t i = 0; i < s.curve.points.size(); ++i) {
                const auto& p = s.curve.points[i];
                if (i) o += ", ";
                o += "[";
                q4(o, p.x); o += ", "; q4(o, p.y); o += ", "; q4(o, p.width);
                o += "]";
            }
            o += "]}";
            break;
        }
        case StrokeKind::Polygon: {
            const auto& pg = s.polygon;
            o += "{\"type\": \"polygon\", ";
            color(o, pg.color, linear);
            if (pg.supersample) o += ", \"supersample\": " + std::to_string(pg.supersample);
            o += ", \"points\": [";
            for (size_t i = 0; i < pg.points.size(); ++i) {
                if (i) o += ", ";
                o += "[";
                q4(o, pg.points[i].x); o += ", "; q4(o, pg.points[i].y);
                o += "]";
            }
            o += "]}";
            break;
        }
    }
}

}  // namespace

std::string export_json(const Document& doc) {
    const Header& h = doc.info.header;
    // Version 2 only when a polygon stroke or anti-aliased curves (format 1.4) need it: other
    // documents export as before.
    bool polygons = h.curve_grid;
    for (const Frame& f : doc.frames)
        for (const Stroke& s : f.added) polygons = polygons || s.kind == StrokeKind::Polygon;
    // Version 3 only for format 1.3 canvases (alpha, colour encoding 1).
    const bool v3 = !h.plain_color();
    const bool linear = h.color == ColorEncoding::LinearHalf;
    std::string o = std::string("{\n  \"format\": \"spt-strokes\",\n  \"version\": ") + (v3 ? "3" : polygons ? "2" : "1") + ",\n";
    const unsigned bg[3] = {linear ? unsigned(h.background.r << 8 | h.background_lo.r) : h.background.r,
                            linear ? unsigned(h.background.g << 8 | h.background_lo.g) : h.background.g,
                            linear ? unsigned(h.background.b << 8 | h.background_lo.b) : h.background.b};
    o += "  \"canvas\": {\"width\": " + std::to_string(h.width) + ", \"height\": " + std::to_string(h.height);
    if (v3) {
        o += ", \"color_encoding\": \"";
        o += color_encoding_name(h.color);
        o += std::string("\", \"alpha\": ") + (h.alpha ? "true" : "false");
    }
    if (h.curve_grid) o += ", \"curve_grid\": true";
    o += ", \"background\": [" + std::to_string(bg[0]) + ", " + std::to_string(bg[1]) + ", " + std::to_string(bg[2]) +
         "], \"fps\": [" + std::to_string(h.fps.num) + ", " + std::to_string(h.fps.den) + "]},\n";
    o += "  \"sets\": [";
    for (size_t i = 0; i < h.sets.size(); ++i)
        o += (i ? ", [" : "[") + std::to_string(h.sets[i].width) + ", " + std::to_string(h.sets[i].height) + "]";
    o += "],\n  \"orientations\": [";
    for (size_t i = 0; i < h.orientations.size(); ++i)
        o += (i ? ", [" : "[") + std::to_string(h.orientations[i].cos_q14) + ", " + std::to_string(h.orientations[i].sin_q14) + "]";
    o += "],\n  \"templates\": [";
    for (size_t i = 0; i < doc.info.templates.size(); ++i) {
        const Template& t = doc.info.templates[i];
        o += i ? ",\n    " : "\n    ";
        o += "{\"kind\": \"";
        o += template_kind_name(t.kind);
        o += "\"";
        if (!t.name.empty()) { o += ", \"name\": "; json::append_string(o, t.name); }
        if (t.supersample) o += ", \"supersample\": " + std::to_string(t.supersample);
        if (t.kind == TemplateKind::Bitmap)
            o += ", \"width\": " + std::to_string(t.width) + ", \"height\": " + std::to_string(t.height) + ", \"base64\": \"" +
                 base64_encode(t.pixels.data(), t.pixels.size()) + "\"";
        o += "}";
    }
    o += "\n  ],\n";
    if (!doc.info.metadata.empty()) {
        o += "  \"metadata\": {";
        for (size_t i = 0; i < doc.info.metadata.size(); ++i) {
            o += i ? ", " : "";
            json::append_string(o, doc.info.metadata[i].first);
            o += ": ";
            json::append_string(o, doc.info.metadata[i].second);
        }
        o += "},\n";
    }
    if (!doc.info.rois.empty()) {
        o += "  \"rois\": [";
        for (size_t i = 0; i < doc.info.rois.size(); ++i) {
            const Roi& r = doc.info.rois[i];
            o += (i ? ", [" : "[") + std::to_string(r.first_frame) + ", " + std::to_string(r.last_frame) + ", " + std::to_string(r.x) +
                 ", " + std::to_string(r.y) + ", " + std::to_string(r.w) + ", " + std::to_string(r.h) + "]";
        }
        o += "],\n";
    }
    o += "  \"frames\": [";
    for (size_t f = 0; f < doc.frames.size(); ++f) {
        const Frame& fr = doc.frames[f];
        o += f ? ",\n    {" : "\n    {";
        o += fr.type == FrameType::Key ? "\"type\": \"key\"" : "\"type\": \"inter\"";
        if (fr.type == FrameType::Inter) {
            o += ", \"removed\": [";
            for (size_t i = 0; i < fr.removed.size(); ++i) o += (i ? ", " : "") + std::to_string(fr.removed[i]);
            o += "]";
            if (!fr.motion.empty()) {
                o += ", \"motion\": {\"block_size\": " + std::to_string(fr.motion.block_size) + ", \"vectors\": [";
                for (size_t i = 0; i < fr.motion.vectors.size(); ++i) {
                    o += i ? ", [" : "[";
                    q4(o, fr.motion.vectors[i].first);
                    o += ", ";
                    q4(o, fr.motion.vectors[i].second);
                    o += "]";
                }
                o += "]}";
            }
        }
        o += ", \"strokes\": [";
        for (size_t i = 0; i < fr.added.size(); ++i) {
            o += i ? ",\n      " : "\n      ";
            stroke(o, fr.added[i], linear);
        }
        o += fr.added.empty() ? "]}" : "\n    ]}";
    }
    o += "\n  ]\n}\n";
    return o;
}

}  // namespace spt::import
