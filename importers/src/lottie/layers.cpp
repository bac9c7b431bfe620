// Times: a layer's properties are evaluated at the time of the composition that holds it (its
// keyframe times are that composition's, start time "st" included, as lottie-web reads them);
// a precomp's layers see (t - st) / sr, or its time remapping.
//
// The composition at a frame: layers bottom to top (shape, solid, precomp, null), their
// transforms with parenting, in and out points, precomps with start time, stretch and time
// remapping, and shape groups as After Effects defines them: a fill or stroke paints every path
// above it in its group (nested groups included, through their transforms), below the items
// above it. Layers and items the format cannot hold are named once each (Ctx::warn).
#include <algorithm>
#include <cmath>

#include "model.hpp"

namespace spt::import::lottie {

namespace {

std::string str(const Value* v) { return v && v->is_string() ? v->text : std::string(); }
double num(const Value* v, double def) { return v && v->is_number() ? v->number : def; }
bool flag(const Value* v) { return v && ((v->type == json::Type::Bool && v->boolean) || (v->is_number() && v->number != 0)); }

// The matrix of a transform object (layer "ks", group "tr") at time t: translate(p) rotate(r)
// skew scale(s / 100) translate(-a), and its opacity (0..1).
Mat2x3 transform(Ctx& c, const Value* ks, double t, double* opacity) {
    if (opacity) *opacity = 1;
    if (!ks || !ks->is_object()) return {};
    auto a = prop(c, ks->find("a"), t, {0, 0});
    std::vector<double> p;
    const Value* pv = ks->find("p");
    if (pv && pv->is_object() && flag(pv->find("s")))  // split position: "x" and "y" apart
        p = {prop1(c, pv->find("x"), t, 0), prop1(c, pv->find("y"), t, 0)};
    else
        p = prop(c, pv, t, {0, 0});
    auto s = prop(c, ks->find("s"), t, {100, 100});
    double r = prop1(c, ks->find("r"), t, 0);
    if (const Value* rz = ks->find("rz")) r = prop1(c, rz, t, r);
    const double sk = prop1(c, ks->find("sk"), t, 0), sa = prop1(c, ks->find("sa"), t, 0);
    a.resize(2);
    p.resize(2);
    s.resize(2, 100);
    if (opacity) *opacity = prop1(c, ks->find("o"), t, 100) / 100;
    Mat2x3 m = Mat2x3::translate(p[0], p[1]) * Mat2x3::rotate_deg(r);
    if (sk != 0) {
        const double tk = std::tan(-sk * M_PI / 180);
        m = m * Mat2x3::rotate_deg(sa) * Mat2x3{1, 0, tk, 1, 0, 0} * Mat2x3::rotate_deg(-sa);
    }
    return m * Mat2x3::scale(s[0] / 100, s[1] / 100) * Mat2x3::translate(-a[0], -a[1]);
}

// A gradient's colour stops averaged ("g": "p" stops of offset, r, g, b): one colour for it.
std::vector<double> gradient_mean(Ctx& c, const Value& it, double t) {
    const Value* g = it.find("g");
    const int n = g ? int(num(g->find("p"), 0)) : 0;
    auto v = g ? prop(c, g->find("k"), t, {}) : std::vector<double>{};
    double r = 0, gg = 0, b = 0;
    int k = 0;
    for (; k < n && size_t(4 * k + 3) < v.size(); ++k) { r += v[4 * k + 1]; gg += v[4 * k + 2]; b += v[4 * k + 3]; }
    if (!k) return {0, 0, 0};
    return {r / k, gg / k, b / k};
}

struct Geo { std::vector<Poly> polys; double scale = 1; bool skewed = false; };

using Ops = std::vector<std::vector<Stroke>>;  // paint operations, top first

void group(Ctx& c, const Value& items, double t, const Mat2x3& m, double opacity, std::vector<Geo>& geo, Ops& ops, int depth) {
    if (!items.is_array()) return;
    if (depth > 64) { c.fail("shape groups nested more than 64 deep"); return; }
    for (const Value& it : items.items) {
        if (!c.ok()) return;
        if (!it.is_object() || flag(it.find("hd"))) continue;
        const std::string ty = str(it.find("ty"));
        if (ty == "sh" || ty == "rc" || ty == "el" || ty == "sr") {
            std::vector<BezPath> paths;
            if (!shape_paths(c, it, t, paths)) return;
            Geo g;
            g.scale = std::sqrt(std::fabs(m.a * m.d - m.b * m.c));
            g.skewed = std::fabs(std::hypot(m.a, m.b) - std::hypot(m.c, m.d)) > 1e-6 * g.scale || std::fabs(m.a * m.c + m.b * m.d) > 1e-6 * g.scale * g.scale;
            for (const BezPath& p : paths) {
                Poly q;
                q.closed = p.closed;
                if (!flatten(c, p, m, q.pts)) return;
                if (!q.pts.empty()) g.polys.push_back(std::move(q));
            }
            geo.push_back(std::move(g));
        } else if (ty == "gr") {
            const Value* sub = it.find("it");
            if (!sub) continue;
            Mat2x3 gm;
            double go = 1;
            for (const Value& s : sub->items)
                if (s.is_object() && str(s.find("ty")) == "tr") gm = transform(c, &s, t, &go);
            std::vector<Geo> child;
            group(c, *sub, t, m * gm, opacity * go, child, ops, depth + 1);
            for (Geo& g : child) geo.push_back(std::move(g));
        } else if (ty == "fl" || ty == "gf") {
            std::vector<double> col = ty == "fl" ? prop(c, it.find("c"), t, {0, 0, 0}) : gradient_mean(c, it, t);
            if (ty == "gf") c.warn("gradient fills are drawn in the mean colour of their stops (the format has one colour a stroke)");
            const double o = prop1(c, it.find("o"), t, 100) / 100 * opacity;
            if (num(it.find("r"), 1) == 2) c.warn("even-odd fills are drawn with the nonzero rule");
            std::vector<Poly> all;
            for (const Geo& g : geo) all.insert(all.end(), g.polys.begin(), g.polys.end());
            std::vector<Stroke> s;
            fill_polys(c, all, colour(col, o), s);
            ops.push_back(std::move(s));
        } else if (ty == "st" || ty == "gs") {
            std::vector<double> col = ty == "st" ? prop(c, it.find("c"), t, {0, 0, 0}) : gradient_mean(c, it, t);
            if (ty == "gs") c.warn("gradient strokes are drawn in the mean colour of their stops");
            const double o = prop1(c, it.find("o"), t, 100) / 100 * opacity;
            // Dashes: "d" entries {"n": "d" dash, "g" gap, "o" offset, "v": length}.
            std::vector<double> pattern;
            double dash_offset = 0;
            if (const Value* d = it.find("d"); d && d->is_array())
                for (const Value& e : d->items) {
                    const std::string n = str(e.find("n"));
                    const double v = prop1(c, e.find("v"), t, 0);
                    if (n == "o") dash_offset = v;
                    else if (n == "d" || n == "g") pattern.push_back(v);
                }
            if (pattern.size() % 2) pattern.insert(pattern.end(), pattern.begin(), pattern.end());  // odd: repeated, as a canvas does
            StrokeStyle st;
            st.cap = int(num(it.find("lc"), 2));
            st.join = int(num(it.find("lj"), 2));
            st.miter = num(it.find("ml"), 4);
            const double w = prop1(c, it.find("w"), t, 1);
            std::vector<Stroke> s;
            for (const Geo& g : geo) {
                if (g.skewed) c.warn("strokes under non-uniform scale or skew are drawn with one width");
                st.width = w * g.scale;
                if (pattern.empty()) {
                    stroke_polys(c, g.polys, st, colour(col, o), s);
                } else {
                    std::vector<double> scaled = pattern;
                    for (double& v : scaled) v *= g.scale;
                    std::vector<Poly> dashed = g.polys;
                    if (!dash(dashed, scaled, dash_offset * g.scale, c.bounds.max_path_vertices)) {
                        c.fail("a dash pattern makes more than " + std::to_string(c.bounds.max_path_vertices) + " dashes on one path");
                        return;
                    }
                    stroke_polys(c, dashed, st, colour(col, o), s);
                }
            }
            ops.push_back(std::move(s));
        } else if (ty == "tm") {
            const double s = prop1(c, it.find("s"), t, 0) / 100, e = prop1(c, it.find("e"), t, 100) / 100;
            const double off = prop1(c, it.find("o"), t, 0) / 360;
            const bool joined = num(it.find("m"), 1) == 2;
            if (joined) {  // "individually": the paths trimmed as one, in order
                if (geo.empty()) continue;
                Geo one;
                one.scale = geo[0].scale;
                for (Geo& g : geo) one.polys.insert(one.polys.end(), g.polys.begin(), g.polys.end());
                trim(one.polys, s, e, off, true);
                geo = {std::move(one)};
            } else {  // "simultaneously": each path trimmed alone
                for (Geo& g : geo) {
                    std::vector<Poly> kept;
                    for (Poly& p : g.polys) {
                        std::vector<Poly> one{std::move(p)};
                        trim(one, s, e, off, false);
                        for (Poly& q : one) kept.push_back(std::move(q));
                    }
                    g.polys = std::move(kept);
                }
            }
        } else if (ty == "tr") {
        } else if (ty == "mm") {
            c.warn("merge paths are drawn unmerged, as lottie-web's canvas renderer draws them");
        } else if (ty == "rd") {
            c.warn("round corners are not applied");
        } else if (ty == "rp") {
            c.warn("repeaters are not applied");
        } else {
            c.warn("shape items of type \"" + ty + "\" are not drawn");
        }
    }
}

struct LayerList {
    const Value* arr = nullptr;
    std::map<int64_t, const Value*> by_ind;
};

// The layer's matrix with its parents' (parents' opacity is not inherited, as in Lottie).
Mat2x3 layer_matrix(Ctx& c, const LayerList& L, const Value& layer, double t, int guard) {
    Mat2x3 m = transform(c, layer.find("ks"), t, nullptr);
    if (const Value* p = layer.find("parent"); p && p->is_number()) {
        if (guard > 64) { c.fail("layer parenting is circular or deeper than 64"); return m; }
        auto it = L.by_ind.find(int64_t(p->number));
        if (it != L.by_ind.end()) m = layer_matrix(c, L, *it->second, t, guard + 1) * m;
    }
    return m;
}

void layers(Ctx& c, const Comp& comp, const Value& arr, double t, const Mat2x3& outer, double outer_o, int depth,
            std::vector<Stroke>& out);

void layer(Ctx& c, const Comp& comp, const LayerList& L, const Value& ly, double t, const Mat2x3& outer, double outer_o,
           int depth, std::vector<Stroke>& out) {
    if (!ly.is_object() || flag(ly.find("hd"))) return;
    if (flag(ly.find("td"))) { c.warn("track mattes are not held by the format: matte layers are not drawn, matted layers are drawn whole"); return; }
    if (flag(ly.find("hasMask")) || (ly.find("masksProperties") && ly.find("masksProperties")->is_array() && !ly.find("masksProperties")->items.empty()))
        c.warn("masks are not held by the format: masked layers are drawn unmasked");
    if (num(ly.find("tt"), 0)) c.warn("track mattes are not held by the format: matte layers are not drawn, matted layers are drawn whole");
    if (flag(ly.find("ddd"))) c.warn("3D layers are drawn flat");
    if (const Value* ef = ly.find("ef"); ef && ef->is_array() && !ef->items.empty()) c.warn("layer effects are not drawn");
    const double ip = num(ly.find("ip"), 0), op = num(ly.find("op"), 0);
    if (t < ip || t >= op) return;
    const double st = num(ly.find("st"), 0), sr = num(ly.find("sr"), 1);
    const int ty = int(num(ly.find("ty"), -1));
    double o = 1;
    transform(c, ly.find("ks"), t, &o);
    const Mat2x3 m = outer * layer_matrix(c, L, ly, t, 0);
    o *= outer_o;
    if (ty == 4) {
        std::vector<Geo> geo;
        Ops ops;
        if (const Value* sh = ly.find("shapes")) group(c, *sh, t, m, o, geo, ops, 0);
        for (auto it = ops.rbegin(); it != ops.rend(); ++it) out.insert(out.end(), it->begin(), it->end());
    } else if (ty == 1) {
        const double w = num(ly.find("sw"), 0), h = num(ly.find("sh"), 0);
        Rgb8 rgb;
        bool none = false;
        std::string sc = str(ly.find("sc"));
        if (sc.size() == 9) sc = sc.substr(0, 7);  // #rrggbbaa
        if (!parse_color(sc, rgb, none)) { c.warn("solid layers with an unreadable colour are drawn black"); rgb = {0, 0, 0}; }
        Poly p;
        p.closed = true;
        for (auto [x, y] : {std::pair{0.0, 0.0}, {w, 0.0}, {w, h}, {0.0, h}}) { Point q; m.apply(x, y, q.x, q.y); p.pts.push_back(q); }
        c.points_done += 4;
        fill_polys(c, {p}, colour({double(rgb.r), double(rgb.g), double(rgb.b), 255.0}, o), out);
    } else if (ty == 0) {
        if (depth + 1 > int(c.bounds.max_precomp_depth)) {
            c.fail("precomps nested deeper than " + std::to_string(c.bounds.max_precomp_depth) + " (or a precomp that contains itself)");
            return;
        }
        auto a = comp.assets.find(str(ly.find("refId")));
        if (a == comp.assets.end()) { c.warn("precomp layers whose asset is missing are not drawn"); return; }
        double ct = (t - st) / (sr != 0 ? sr : 1);
        if (const Value* tm = ly.find("tm")) ct = prop1(c, tm, t, 0) * comp.fr;
        layers(c, comp, *a->second, ct, m, o, depth + 1, out);
    } else if (ty == 2) {
        c.warn("image layers are not drawn (the format has no image strokes)");
    } else if (ty == 5) {
        c.warn("text layers are not drawn (the format holds no glyphs; convert text to shapes)");
    } else if (ty != 3) {
        c.warn("layers of type " + std::to_string(ty) + " are not drawn");
    }
}

void layers(Ctx& c, const Comp& comp, const Value& arr, double t, const Mat2x3& outer, double outer_o, int depth,
            std::vector<Stroke>& out) {
    if (!arr.is_array()) return;
    LayerList L;
    L.arr = &arr;
    for (const Value& ly : arr.items)
        if (ly.is_object())
            if (const Value* ind = ly.find("ind"); ind && ind->is_number()) L.by_ind[int64_t(ind->number)] = &ly;
    for (auto it = arr.items.rbegin(); it != arr.items.rend() && c.ok(); ++it) layer(c, comp, L, *it, t, outer, outer_o, depth, out);
}

}  // namespace

bool render_comp(Ctx& c, const Comp& comp, double t, std::vector<Stroke>& out) {
    if (const Value* ls = comp.root->find("layers")) layers(c, comp, *ls, t, {}, 1, 0, out);
    return c.ok();
}

}  // namespace spt::import::lottie
