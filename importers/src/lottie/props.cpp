// Keyframed Lottie properties at a frame: static values, keyframes with cubic Bezier easing
// per dimension (bodymovin's "o"/"i" handles), hold keyframes, old files' "e" end values, and
// the spatial tangents ("to"/"ti") of moving positions, followed by arc length as lottie-web does.
#include <algorithm>
#include <cmath>

#include "model.hpp"

namespace spt::import::lottie {

namespace {

std::vector<double> numbers(const Value* v) {
    std::vector<double> r;
    if (!v) return r;
    if (v->is_number()) r.push_back(v->number);
    else if (v->is_array())
        for (const Value& x : v->items)
            if (x.is_number()) r.push_back(x.number);
    return r;
}

// One easing handle component for dimension d (arrays per dimension or one scalar).
double handle(const Value* h, const char* axis, size_t d, double def) {
    if (!h || !h->is_object()) return def;
    const Value* a = h->find(axis);
    if (!a) return def;
    if (a->is_number()) return a->number;
    if (a->is_array() && !a->items.empty()) {
        const Value& x = a->items[std::min(d, a->items.size() - 1)];
        if (x.is_number()) return x.number;
    }
    return def;
}

double cubic(double a, double b, double u) {  // Bezier from 0 to 1 with control values a, b
    const double v = 1 - u;
    return 3 * v * v * u * a + 3 * v * u * u * b + u * u * u;
}

// y at x of the easing curve (0,0), (x1,y1), (x2,y2), (1,1): bisection on the monotone x(u).
double ease(double x1, double y1, double x2, double y2, double p) {
    if (p <= 0) return 0;
    if (p >= 1) return 1;
    x1 = std::clamp(x1, 0.0, 1.0);
    x2 = std::clamp(x2, 0.0, 1.0);
    double lo = 0, hi = 1, u = p;
    for (int k = 0; k < 50; ++k) {
        u = 0.5 * (lo + hi);
        if (cubic(x1, x2, u) < p) lo = u; else hi = u;
    }
    return cubic(y1, y2, u);
}

bool is_keyframes(const Value* k) {
    return k && k->is_array() && !k->items.empty() && k->items[0].is_object() && k->items[0].find("t");
}

}  // namespace

Rgba8 colour(const std::vector<double>& rgb, double opacity) {
    // bodymovin 4 and later write 0..1; older files 0..255.
    const bool bytes = rgb.size() >= 3 && (rgb[0] > 1 || rgb[1] > 1 || rgb[2] > 1);
    auto ch = [&](size_t i) {
        const double v = i < rgb.size() ? rgb[i] : 0;
        return uint8_t(std::lround(std::clamp(bytes ? v : v * 255.0, 0.0, 255.0)));
    };
    Rgba8 c;
    c.r = ch(0); c.g = ch(1); c.b = ch(2);
    c.a = uint8_t(std::lround(std::clamp(opacity, 0.0, 1.0) * 255.0));
    return c;
}

void check_expression(Ctx& c, const Value* p) {
    if (p && p->is_object())
        if (const Value* x = p->find("x"); x && x->is_string())
            c.warn("expressions are not evaluated (their keyframed or static values are used)");
}

// Finds the keyframe segment of t: index k and the eased progress per dimension (dims values).
// Returns false when t is before the first or past the last keyframe (then `k` is that one).
static bool segment(Ctx& c, const Value& kfs, double t, size_t dims, size_t& k, std::vector<double>& prog, bool& hold) {
    const auto& K = kfs.items;
    if (K.size() > c.bounds.max_keyframes) {
        c.fail("a property has " + std::to_string(K.size()) + " keyframes, above the limit of " + std::to_string(c.bounds.max_keyframes));
        k = 0;
        return false;
    }
    auto time = [&](size_t i) { const Value* tv = K[i].find("t"); return tv && tv->is_number() ? tv->number : 0.0; };
    hold = false;
    if (t <= time(0) || K.size() == 1) { k = 0; return false; }
    size_t i = 0;
    while (i + 1 < K.size() && t >= time(i + 1)) ++i;
    if (i + 1 >= K.size()) { k = i; return false; }
    k = i;
    const Value& a = K[i];
    const Value* h = a.find("h");
    hold = h && h->is_number() && h->number == 1;
    const double span = time(i + 1) - time(i);
    const double p = span > 0 ? (t - time(i)) / span : 1;
    prog.assign(std::max<size_t>(dims, 1), p);
    for (size_t d = 0; d < prog.size(); ++d)
        prog[d] = ease(handle(a.find("o"), "x", d, 0), handle(a.find("o"), "y", d, 0), handle(a.find("i"), "x", d, 1),
                       handle(a.find("i"), "y", d, 1), p);
    return true;
}

// Start and end values of segment k: "s" of k, and "e" of k (old files) or "s" of k + 1.
static void ends(const Value& kfs, size_t k, const Value*& s, const Value*& e) {
    const auto& K = kfs.items;
    s = K[k].find("s");
    e = K[k].find("e");
    if (!e && k + 1 < K.size()) e = K[k + 1].find("s");
    if (!s && k > 0) s = K[k - 1].find("e");
}

std::vector<double> prop(Ctx& c, const Value* p, double t, std::vector<double> def) {
    if (!p || !p->is_object()) return def;
    check_expression(c, p);
    const Value* k = p->find("k");
    if (!k) return def;
    if (!is_keyframes(k)) {
        auto v = numbers(k);
        return v.empty() ? def : v;
    }
    size_t i = 0;
    std::vector<double> prog;
    bool hold = false;
    const Value *s = nullptr, *e = nullptr;
    ends(*k, 0, s, e);
    const size_t dims = numbers(s).size();
    if (!segment(c, *k, t, dims, i, prog, hold)) {
        // Before the first keyframe: its start; past the last: its value ("s", or the previous "e").
        ends(*k, i, s, e);
        auto v = numbers(k->items[i].find("s"));
        if (v.empty() && i > 0) v = numbers(k->items[i - 1].find("e"));
        if (v.empty()) v = numbers(s);
        return v.empty() ? def : v;
    }
    ends(*k, i, s, e);
    auto a = numbers(s), b = numbers(e);
    if (a.empty()) return def;
    if (hold || b.size() != a.size()) return a;
    // Spatial tangents: the value runs along the Bezier a, a + to, b + ti, b by arc length.
    auto to = numbers(k->items[i].find("to")), ti = numbers(k->items[i].find("ti"));
    if (a.size() >= 2 && to.size() >= 2 && ti.size() >= 2 && (to[0] || to[1] || ti[0] || ti[1])) {
        constexpr int N = 150;  // lottie-web's samples of a spatial segment
        std::vector<Vec> pts(N + 1);
        std::vector<double> len(N + 1, 0);
        for (int j = 0; j <= N; ++j) {
            const double u = double(j) / N, v = 1 - u;
            const double w0 = v * v * v, w1 = 3 * v * v * u, w2 = 3 * v * u * u, w3 = u * u * u;
            pts[j] = {w0 * a[0] + w1 * (a[0] + to[0]) + w2 * (b[0] + ti[0]) + w3 * b[0],
                      w0 * a[1] + w1 * (a[1] + to[1]) + w2 * (b[1] + ti[1]) + w3 * b[1]};
            if (j) len[j] = len[j - 1] + std::hypot(pts[j].x - pts[j - 1].x, pts[j].y - pts[j - 1].y);
        }
        const double target = std::clamp(prog[0], 0.0, 1.0) * len[N];
        int j = 1;
        while (j < N && len[j] < target) ++j;
        const double seg = len[j] - len[j - 1];
        const double f = seg > 0 ? (target - len[j - 1]) / seg : 0;
        std::vector<double> r = a;
        r[0] = pts[j - 1].x + f * (pts[j].x - pts[j - 1].x);
        r[1] = pts[j - 1].y + f * (pts[j].y - pts[j - 1].y);
        for (size_t d = 2; d < a.size(); ++d) r[d] = a[d] + prog[0] * (b[d] - a[d]);
        return r;
    }
    std::vector<double> r(a.size());
    for (size_t d = 0; d < a.size(); ++d) r[d] = a[d] + prog[std::min(d, prog.size() - 1)] * (b[d] - a[d]);
    return r;
}

double prop1(Ctx& c, const Value* p, double t, double def) {
    auto v = prop(c, p, t, {def});
    return v.empty() ? def : v[0];
}

// ---- shape values (paths) ----

static bool read_shape(Ctx& c, const Value* v, BezPath& out) {
    if (v && v->is_array() && !v->items.empty()) v = &v->items[0];  // keyframe "s": [shape]
    if (!v || !v->is_object()) return false;
    auto pairs = [&](const char* key, std::vector<Vec>& dst) {
        dst.clear();
        const Value* a = v->find(key);
        if (!a || !a->is_array()) return;
        if (a->items.size() > c.bounds.max_path_vertices) {
            c.fail("a path has " + std::to_string(a->items.size()) + " vertices, above the limit of " +
                   std::to_string(c.bounds.max_path_vertices));
            return;
        }
        for (const Value& p : a->items) {
            auto n = numbers(&p);
            dst.push_back({n.size() > 0 ? n[0] : 0, n.size() > 1 ? n[1] : 0});
        }
    };
    pairs("v", out.v);
    pairs("i", out.i);
    pairs("o", out.o);
    out.i.resize(out.v.size());
    out.o.resize(out.v.size());
    const Value* cl = v->find("c");
    out.closed = cl && cl->type == json::Type::Bool && cl->boolean;
    return c.ok();
}

bool shape_value(Ctx& c, const Value* ks, double t, BezPath& out) {
    out = {};
    if (!ks || !ks->is_object()) return false;
    check_expression(c, ks);
    const Value* k = ks->find("k");
    if (!is_keyframes(k)) return read_shape(c, k, out);
    size_t i = 0;
    std::vector<double> prog;
    bool hold = false;
    if (!segment(c, *k, t, 1, i, prog, hold)) {
        const Value* s = k->items[i].find("s");
        if (!s && i > 0) s = k->items[i - 1].find("e");
        return read_shape(c, s, out);
    }
    const Value *s = nullptr, *e = nullptr;
    ends(*k, i, s, e);
    BezPath a, b;
    if (!read_shape(c, s, a)) return false;
    if (hold || !e || !read_shape(c, e, b) || b.v.size() != a.v.size()) { out = a; return c.ok(); }
    const double f = prog[0];
    out = a;
    for (size_t j = 0; j < a.v.size(); ++j) {
        out.v[j] = {a.v[j].x + f * (b.v[j].x - a.v[j].x), a.v[j].y + f * (b.v[j].y - a.v[j].y)};
        out.i[j] = {a.i[j].x + f * (b.i[j].x - a.i[j].x), a.i[j].y + f * (b.i[j].y - a.i[j].y)};
        out.o[j] = {a.o[j].x + f * (b.o[j].x - a.o[j].x), a.o[j].y + f * (b.o[j].y - a.o[j].y)};
    }
    return true;
}

}  // namespace spt::import::lottie
