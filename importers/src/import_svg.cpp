// Importer for the SVG that shape-approximation tools write (fogleman/primitive, geometrize):
// rect, circle, ellipse, polygon, polyline, line under nested transforms, with fill,
// fill-opacity, opacity and a background rect. Paths, text and gradients are rejected with a
// message naming the element and line (see importers/README.md).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "spt_import/geometrize.hpp"
#include "spt_import/importer.hpp"
#include "spt_import/shapes.hpp"
#include "spt_import/xml.hpp"

namespace spt::import {

namespace {

using Node = pugi::xml_node;

// 8 x 8 samples: within 0.2 dB of 16 x 16 against primitive's PNGs, a quarter of the work.
constexpr uint8_t kSvgSupersample = 8;

struct Style {
    Rgb8 fill{0, 0, 0};
    bool fill_none = false;
    double fill_opacity = 1, opacity = 1;
    Rgb8 stroke{0, 0, 0};
    bool stroke_none = true;
    double stroke_opacity = 1, stroke_width = 1;
};

class SvgReader {
public:
    SvgReader(const std::string& src, const ImportOptions& o) : src_(src), opts_(o) {}

    Result<Document> run(std::string text) {
        auto parsed = xml::Document::parse(std::move(text), src_);
        if (!parsed) return parsed.error();
        xml_ = std::move(*parsed);
        const Node root = xml_->root();
        if (xml::local_name(root) != "svg") return err(root, std::string("the root element is <") + root.name() + ">, not <svg>");
        Mat2x3 base;
        if (!canvas(root, base)) return e_;
        doc_.info.templates = default_templates();
        // geometrize's SVG (its exporter's signature: SVG Tiny 1.2 with an https namespace)
        // holds the pixel-index geometry of its own aliased rasteriser: emulate that
        // (spt_import/geometrize.hpp). Other SVG renderers (browsers, primitive's PNG output)
        // anti-alias: sample each pixel on a grid (SPEC.md 3.2) so that edges are as soft.
        geometrize_ = std::string_view(root.attribute("baseProfile").value()) == "tiny" &&
                      std::string_view(root.attribute("xmlns").value()) == "https://www.w3.org/2000/svg";
        if (geometrize_) {
            auto r = Renderer::create(doc_.info.header, doc_.info.templates);
            if (!r) return r.error();
            renderer_ = std::move(*r);
            doc_.report.note("geometrize SVG: shapes placed on geometrize's pixel grid and rasterised as it does");
        } else {
            for (auto& t : doc_.info.templates) t.supersample = kSvgSupersample;
        }
        doc_.frames.resize(1);
        // One stroke a shape, mostly: reserving spares the growth copies of a long list (pages
        // that are never written are never resident).
        doc_.frames[0].added.reserve(std::min<size_t>(xml_->elements(), opts_.limits.max_strokes_per_frame));
        Style st;
        if (!style(root, st)) return e_;
        if (!children(root, base, st, 0)) return e_;
        doc_.report.background_stated = background_found_;
        if (opts_.background) doc_.info.header.background = *opts_.background;
        if (geometrize_) {
            if (differing_)
                doc_.report.note("geometrize's scanline rasterisation reproduced by fitted affine and polygon strokes; " +
                                 std::to_string(differing_) + " shape pixels differ from it");
            const Header& h = doc_.info.header;
            for (const Stroke& s : canvas_strip_strokes(h.width, h.height, h.background, 1)) doc_.frames[0].added.push_back(s);
            doc_.canvas_strips = true;
        }
        if (opts_.fps) doc_.info.header.fps = *opts_.fps;
        if (Status s = validate(doc_, src_, opts_.limits); !s) return s.error();
        return std::move(doc_);
    }

private:
    const std::string& src_;
    const ImportOptions& opts_;
    Document doc_;
    std::unique_ptr<xml::Document> xml_;
    Error e_;
    bool any_stroke_ = false;  // a background rect is only recognised before the first stroke
    bool geometrize_ = false;
    std::unique_ptr<Renderer> renderer_;  // geometrize mode: fits strokes to its pixels
    uint64_t differing_ = 0;
    bool background_found_ = false;

    Error err(Node el, const std::string& what) {
        return make_error(Code::Corrupt, src_ + ":" + std::to_string(xml_->line(el)) + ": <" + el.name() + ">: " + what);
    }
    bool fail(Node el, const std::string& what) { e_ = err(el, what); return false; }

    // A length: a number, optionally with "px" (other units and percentages are not supported).
    bool length(Node el, const char* name, double& out, bool required, double dflt = 0) {
        const pugi::xml_attribute a = el.attribute(name);
        if (!a) {
            if (required) return fail(el, std::string("missing attribute ") + name);
            out = dflt;
            return true;
        }
        std::string_view v = a.value();
        while (!v.empty() && v.back() == ' ') v.remove_suffix(1);
        if (v.size() > 2 && v.substr(v.size() - 2) == "px") v.remove_suffix(2);
        if (!parse_number(v, out)) return fail(el, std::string("attribute ") + name + "=\"" + a.value() + "\" is not a number (units other than px are not supported)");
        return true;
    }

    // Numbers separated by whitespace and/or commas ("1,2 3-4" is 1, 2, 3, -4 as SVG allows).
    bool numbers(Node el, std::string_view s, std::vector<double>& out, const char* what) {
        size_t i = 0;
        while (i < s.size()) {
            while (i < s.size() && (s[i] == ' ' || s[i] == ',' || s[i] == '\t' || s[i] == '\n' || s[i] == '\r')) ++i;
            if (i >= s.size()) break;
            size_t b = i;
            if (s[i] == '+' || s[i] == '-') ++i;
            while (i < s.size() && std::isdigit((unsigned char)s[i])) ++i;
            if (i < s.size() && s[i] == '.') { ++i; while (i < s.size() && std::isdigit((unsigned char)s[i])) ++i; }
            if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
                size_t k = i + 1;
                if (k < s.size() && (s[k] == '+' || s[k] == '-')) ++k;
                if (k < s.size() && std::isdigit((unsigned char)s[k])) { i = k; while (i < s.size() && std::isdigit((unsigned char)s[i])) ++i; }
            }
            double v;
            if (i == b || !parse_number(s.substr(b, i - b), v)) return fail(el, std::string("bad number in ") + what + " near \"" + std::string(s.substr(b, 12)) + "\"");
            out.push_back(v);
            if (out.size() > 2 * 65536) return fail(el, std::string(what) + " has too many numbers");
        }
        return true;
    }

    bool transform(Node el, Mat2x3& m) {
        const pugi::xml_attribute a = el.attribute("transform");
        if (!a) return true;
        const std::string_view s = a.value();
        size_t i = 0;
        Mat2x3 t;
        for (;;) {
            while (i < s.size() && (std::isspace((unsigned char)s[i]) || s[i] == ',')) ++i;
            if (i >= s.size()) break;
            size_t b = i;
            while (i < s.size() && std::isalpha((unsigned char)s[i])) ++i;
            std::string_view fn = s.substr(b, i - b);
            while (i < s.size() && std::isspace((unsigned char)s[i])) ++i;
            if (i >= s.size() || s[i] != '(') return fail(el, "bad transform \"" + std::string(s) + "\"");
            size_t close = s.find(')', i);
            if (close == std::string_view::npos) return fail(el, "unterminated transform \"" + std::string(s) + "\"");
            std::vector<double> v;
            if (!numbers(el, s.substr(i + 1, close - i - 1), v, "transform")) return false;
            i = close + 1;
            auto argc_ok = [&](std::initializer_list<size_t> ok) {
                for (size_t n : ok) if (v.size() == n) return true;
                return false;
            };
            Mat2x3 f;
            if (fn == "matrix" && argc_ok({6})) f = {v[0], v[1], v[2], v[3], v[4], v[5]};
            else if (fn == "translate" && argc_ok({1, 2})) f = Mat2x3::translate(v[0], v.size() > 1 ? v[1] : 0);
            else if (fn == "scale" && argc_ok({1, 2})) f = Mat2x3::scale(v[0], v.size() > 1 ? v[1] : v[0]);
            else if (fn == "rotate" && argc_ok({1, 3})) {
                f = Mat2x3::rotate_deg(v[0]);
                if (v.size() == 3) f = Mat2x3::translate(v[1], v[2]) * f * Mat2x3::translate(-v[1], -v[2]);
            } else if (fn == "skewX" && argc_ok({1})) f = {1, 0, std::tan(v[0] * M_PI / 180), 1, 0, 0};
            else if (fn == "skewY" && argc_ok({1})) f = {1, std::tan(v[0] * M_PI / 180), 0, 1, 0, 0};
            else return fail(el, "unsupported transform " + std::string(fn) + " with " + std::to_string(v.size()) + " arguments");
            t = t * f;
        }
        m = m * t;
        return true;
    }

    bool canvas(Node root, Mat2x3& base) {
        double w = 0, h = 0;
        std::vector<double> vb;
        if (const pugi::xml_attribute a = root.attribute("viewBox")) {
            if (!numbers(root, a.value(), vb, "viewBox")) return false;
            if (vb.size() != 4 || !(vb[2] > 0) || !(vb[3] > 0)) return fail(root, "viewBox must be \"min-x min-y width height\" with positive size");
        }
        const bool has_w = root.attribute("width") && !std::strchr(root.attribute("width").value(), '%');
        const bool has_h = root.attribute("height") && !std::strchr(root.attribute("height").value(), '%');
        if (has_w && !length(root, "width", w, true)) return false;
        if (has_h && !length(root, "height", h, true)) return false;
        if (!has_w) w = vb.empty() ? 0 : vb[2];
        if (!has_h) h = vb.empty() ? 0 : vb[3];
        if (!(w >= 1) || !(h >= 1)) return fail(root, "the canvas size is missing (width/height or viewBox) or below 1 px");
        if (w > opts_.limits.max_width || h > opts_.limits.max_height || w * h > double(opts_.limits.max_pixels))
            return fail(root, "canvas " + std::to_string(int64_t(w)) + "x" + std::to_string(int64_t(h)) + " is above the limits");
        const uint32_t W = uint32_t(std::lround(w)), H = uint32_t(std::lround(h));
        doc_.info.header = default_header(W, H, Rgb8{255, 255, 255});
        if (!vb.empty()) {
            // preserveAspectRatio="none" semantics: each axis scaled on its own. Tools write
            // viewBoxes with the canvas's aspect ratio, where this equals the default.
            base = Mat2x3::scale(W / vb[2], H / vb[3]) * Mat2x3::translate(-vb[0], -vb[1]);
        }
        return true;
    }

    bool opacity_value(Node el, const std::string& name, std::string_view v, double& out) {
        bool pct = !v.empty() && v.back() == '%';
        if (pct) v.remove_suffix(1);
        if (!parse_number(v, out)) return fail(el, name + "=\"" + std::string(v) + "\" is not a number");
        if (pct) out /= 100;
        out = std::clamp(out, 0.0, 1.0);
        return true;
    }

    bool property(Node el, const std::string& name, std::string_view v, Style& st) {
        while (!v.empty() && std::isspace((unsigned char)v.front())) v.remove_prefix(1);
        while (!v.empty() && std::isspace((unsigned char)v.back())) v.remove_suffix(1);
        if (v == "inherit") return true;
        if (name == "fill" || name == "stroke") {
            Rgb8 c;
            bool none;
            if (!parse_color(v, c, none)) return fail(el, name + "=\"" + std::string(v) + "\": unsupported colour (gradients and patterns are not imported)");
            if (name == "fill") { st.fill = c; st.fill_none = none; }
            else { st.stroke = c; st.stroke_none = none; }
        } else if (name == "fill-opacity") return opacity_value(el, name, v, st.fill_opacity);
        else if (name == "stroke-opacity") return opacity_value(el, name, v, st.stroke_opacity);
        else if (name == "opacity") {
            double o;
            if (!opacity_value(el, name, v, o)) return false;
            st.opacity *= o;  // group opacity folded into each child (exact for one child)
        } else if (name == "stroke-width") {
            std::string_view n = v;
            if (n.size() > 2 && n.substr(n.size() - 2) == "px") n.remove_suffix(2);
            if (!parse_number(n, st.stroke_width) || st.stroke_width < 0) return fail(el, "bad stroke-width \"" + std::string(v) + "\"");
        }
        return true;
    }

    bool style(Node el, Style& st) {
        static const char* props[] = {"fill", "fill-opacity", "opacity", "stroke", "stroke-opacity", "stroke-width"};
        for (const char* p : props)
            if (const pugi::xml_attribute a = el.attribute(p))
                if (!property(el, p, a.value(), st)) return false;
        if (const pugi::xml_attribute a = el.attribute("style")) {
            // CSS declarations override presentation attributes.
            std::string_view s = a.value();
            while (!s.empty()) {
                size_t semi = s.find(';');
                std::string_view decl = s.substr(0, semi);
                s = semi == std::string_view::npos ? std::string_view() : s.substr(semi + 1);
                size_t colon = decl.find(':');
                if (colon == std::string_view::npos) continue;
                std::string_view k = decl.substr(0, colon);
                while (!k.empty() && std::isspace((unsigned char)k.front())) k.remove_prefix(1);
                while (!k.empty() && std::isspace((unsigned char)k.back())) k.remove_suffix(1);
                if (!property(el, std::string(k), decl.substr(colon + 1), st)) return false;
            }
        }
        if (st.opacity < 1 && el.first_child()) {
            size_t shapes = 0;
            for (Node c : el.children())
                shapes += c.type() == pugi::node_element && xml::local_name(c) != "title" && xml::local_name(c) != "desc";
            if (shapes > 1) doc_.report.note("group opacity applied to each shape of the group (overlaps inside the group differ)");
        }
        return true;
    }

    static uint8_t alpha(double o) { return uint8_t(std::lround(std::clamp(o, 0.0, 1.0) * 255)); }

    Rgba8 fill_color(const Style& st) const {
        return {st.fill.r, st.fill.g, st.fill.b, alpha(st.fill_opacity * st.opacity)};
    }

    bool count_ok(Node el) {
        if (doc_.frames[0].added.size() >= opts_.limits.max_strokes_per_frame) return fail(el, "more shapes than the stroke limit");
        return true;
    }

    // Outline strokes of closed shapes are not in the stroke model: say so once.
    void stroke_note(const Style& st) {
        if (!st.stroke_none && st.stroke_width > 0 && st.stroke_opacity * st.opacity > 0)
            doc_.report.note("outline strokes of filled shapes ignored (only lines and polylines become curves)");
    }

    // geometrize's SVG element -> its shape type and data (pixel indices; see geometrize.hpp).
    bool geometrize_shape(Node el, std::string_view n, const Mat2x3& m, Rgba8 col) {
        auto snap = [](double v) { const double r = std::round(v); return std::fabs(v - r) < 1e-3 ? r : v; };
        int type = 0;
        std::vector<double> d;
        if (n == "rect") {
            double x, y, w, h, x0, y0, x1, y1;
            if (!length(el, "x", x, false) || !length(el, "y", y, false) || !length(el, "width", w, true) || !length(el, "height", h, true)) return false;
            m.apply(x, y, x0, y0);
            m.apply(x + w, y + h, x1, y1);
            type = 1;
            d = {snap(x0), snap(y0), snap(x1), snap(y1)};
        } else if (n == "circle" || n == "ellipse") {
            double cx, cy, rx, ry, x, y;
            if (!length(el, "cx", cx, false) || !length(el, "cy", cy, false)) return false;
            if (n == "circle") {
                if (!length(el, "r", rx, true)) return false;
                ry = rx;
            } else if (!length(el, "rx", rx, true) || !length(el, "ry", ry, true)) return false;
            m.apply(cx, cy, x, y);
            const double sx = rx * std::hypot(m.a, m.b), sy = ry * std::hypot(m.c, m.d);
            const double deg = std::atan2(m.b, m.a) * 180.0 / 3.14159265358979323846;
            if (std::fabs(m.b) < 1e-9 && std::fabs(m.c) < 1e-9) {
                type = (n == "circle" && sx == sy) ? 32 : 8;
                d = type == 32 ? std::vector<double>{snap(x), snap(y), snap(sx)} : std::vector<double>{snap(x), snap(y), snap(sx), snap(sy)};
            } else {
                type = 16;
                d = {snap(x), snap(y), snap(sx), snap(sy), snap(deg < 0 ? deg + 360 : deg)};
            }
        } else {
            const pugi::xml_attribute a = el.attribute("points");
            if (!a) return fail(el, "missing attribute points");
            std::vector<double> v;
            if (!numbers(el, a.value(), v, "points")) return false;
            if (v.size() % 2 || v.size() < 6) return fail(el, "points needs at least three x, y pairs");
            for (size_t i = 0; i + 1 < v.size(); i += 2) {
                double x, y;
                m.apply(v[i], v[i + 1], x, y);
                d.push_back(snap(x));
                d.push_back(snap(y));
            }
            type = d.size() == 6 ? 4 : geometrize::kExplicitPolygon;
        }
        for (double v : d)
            if (!(std::fabs(v) <= double(1 << 20))) return fail(el, "coordinates outside +-2^20");
        ++doc_.report.shapes;
        const Header& h = doc_.info.header;
        geometrize::append_shape(*renderer_, type, d, col, h.width, h.height, doc_.frames[0].added, doc_.report, differing_);
        any_stroke_ = true;
        return true;
    }

    bool shape(Node el, const Mat2x3& m, const Style& st) {
        if (!count_ok(el)) return false;
        auto& out = doc_.frames[0].added;
        StrokeSink sink(out, doc_.report);
        if (!geometrize_) sink.set_polygon_supersample(kSvgSupersample);
        const std::string_view n = xml::local_name(el);
        const Rgba8 col = fill_color(st);
        if (geometrize_ && !st.fill_none && (n == "rect" || n == "circle" || n == "ellipse" || n == "polygon"))
            return geometrize_shape(el, n, m, col);
        if (n == "rect") {
            double x, y, w, h;
            if (!length(el, "x", x, false) || !length(el, "y", y, false) || !length(el, "width", w, true) || !length(el, "height", h, true)) return false;
            if (w < 0 || h < 0) return fail(el, "negative width or height");
            if (el.attribute("rx") || el.attribute("ry")) doc_.report.note("rounded rectangle corners (rx, ry) ignored");
            stroke_note(st);
            if (st.fill_none || w == 0 || h == 0) return true;
            // A first, opaque, axis-aligned rect covering the canvas is the background colour.
            if (!any_stroke_ && col.a == 255 && m.b == 0 && m.c == 0) {
                double x0, y0, x1, y1;
                m.apply(x, y, x0, y0);
                m.apply(x + w, y + h, x1, y1);
                const Header& hd = doc_.info.header;
                if (std::min(x0, x1) <= 0 && std::min(y0, y1) <= 0 && std::max(x0, x1) >= hd.width && std::max(y0, y1) >= hd.height) {
                    doc_.info.header.background = st.fill;
                    background_found_ = true;
                    return true;
                }
            }
            ++doc_.report.shapes;
            sink.rect(m, x, y, w, h, col);
        } else if (n == "circle" || n == "ellipse") {
            double cx, cy, rx, ry;
            if (!length(el, "cx", cx, false) || !length(el, "cy", cy, false)) return false;
            if (n == "circle") {
                if (!length(el, "r", rx, true)) return false;
                ry = rx;
            } else if (!length(el, "rx", rx, true) || !length(el, "ry", ry, true)) return false;
            if (rx < 0 || ry < 0) return fail(el, "negative radius");
            stroke_note(st);
            if (st.fill_none || rx == 0 || ry == 0) return true;
            ++doc_.report.shapes;
            sink.ellipse(m, cx, cy, rx, ry, col);
        } else if (n == "polygon" || n == "polyline" || n == "line") {
            std::vector<double> v;
            if (n == "line") {
                double x1, y1, x2, y2;
                if (!length(el, "x1", x1, false) || !length(el, "y1", y1, false) || !length(el, "x2", x2, false) || !length(el, "y2", y2, false)) return false;
                v = {x1, y1, x2, y2};
            } else {
                const pugi::xml_attribute a = el.attribute("points");
                if (!a) return fail(el, "missing attribute points");
                if (!numbers(el, a.value(), v, "points")) return false;
                if (v.size() % 2) return fail(el, "points has an odd count of numbers");
            }
            std::vector<Point> pts;
            for (size_t i = 0; i + 1 < v.size(); i += 2) {
                Point p;
                m.apply(v[i], v[i + 1], p.x, p.y);
                pts.push_back(p);
            }
            if (n == "polygon" || (n == "polyline" && !st.fill_none && st.stroke_none)) {
                if (n == "polygon") stroke_note(st);
                if (!st.fill_none) sink.polygon(pts, col);
            } else if (!st.stroke_none) {
                // Stroke width scales with the transform's mean scale (exact for similarity maps).
                const double scale = std::sqrt(std::fabs(m.a * m.d - m.b * m.c));
                const Rgba8 sc{st.stroke.r, st.stroke.g, st.stroke.b, alpha(st.stroke_opacity * st.opacity)};
                sink.polyline(pts, st.stroke_width * scale, sc);
                doc_.report.note("lines drawn with round caps and joins");
            }
        }
        if (!out.empty()) any_stroke_ = true;
        return true;
    }

    // Each child is released once read, so the nodes of a large flat document are freed while
    // the stroke list grows.
    bool children(Node parent, const Mat2x3& m, const Style& st, int depth) {
        for (Node c = parent.first_child(), next; c; c = next) {
            next = c.next_sibling();
            if (!child(c, m, st, depth)) return false;
            xml_->release(c);
        }
        return true;
    }

    bool child(Node c, const Mat2x3& m, const Style& st, int depth) {
        if (c.type() != pugi::node_element) return true;  // character data
        const std::string_view n = xml::local_name(c);
        if (n == "title" || n == "desc" || n == "metadata" || n == "defs" || n == "style") {
            if (n == "style" || n == "defs") doc_.report.note(std::string("<").append(n).append("> content ignored"));
            return true;
        }
        Style cs = st;
        Mat2x3 cm = m;
        if (!transform(c, cm) || !style(c, cs)) return false;
        if (n == "g" || n == "a" || n == "svg") {
            if (n == "svg") doc_.report.note("nested <svg> treated as a group (its viewport is ignored)");
            return children(c, cm, cs, depth + 1);
        }
        if (n == "rect" || n == "circle" || n == "ellipse" || n == "polygon" || n == "polyline" || n == "line")
            return shape(c, cm, cs);
        return fail(c, "unsupported element (importable: g, rect, circle, ellipse, polygon, polyline, line)");
    }
};

bool sniff(const std::string& path, std::string_view head) {
    if (path.size() >= 4) {
        std::string ext = path.substr(path.size() - 4);
        for (auto& ch : ext) ch = char(std::tolower((unsigned char)ch));
        if (ext == ".svg") return true;
    }
    return head.find("<svg") != std::string_view::npos;
}

Result<Document> load(const std::string& path, std::string text, const ImportOptions& opts) {
    SvgReader r(path, opts);
    return r.run(std::move(text));
}

}  // namespace

extern const Importer kSvgImporter = {"svg", "SVG of shape painters (primitive, geometrize): rect, circle, ellipse, polygon, line", sniff, load};

}  // namespace spt::import
