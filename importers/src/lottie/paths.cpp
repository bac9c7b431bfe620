// Lottie shapes as Bezier paths (paths, rectangles, ellipses, polystars, laid out as lottie-web
// lays them out, so that directions and trim paths agree), their flattening to polylines within
// the tolerance in canvas pixels, and trim paths on the flattened polylines.
#include <algorithm>
#include <cmath>

#include "model.hpp"

namespace spt::import::lottie {

namespace {

constexpr double kKappa = 0.5519150244935105707435627;  // cubic quarter circle handle

bool reversed(const Value& item) {
    const Value* d = item.find("d");
    return d && d->is_number() && d->number == 3;
}

void reverse(BezPath& p) {
    std::reverse(p.v.begin(), p.v.end());
    std::reverse(p.i.begin(), p.i.end());
    std::reverse(p.o.begin(), p.o.end());
    std::swap(p.i, p.o);
}

BezPath rect(Ctx& c, const Value& it, double t) {
    auto p = prop(c, it.find("p"), t, {0, 0});
    auto s = prop(c, it.find("s"), t, {0, 0});
    p.resize(2);
    s.resize(2);
    double r = std::min(prop1(c, it.find("r"), t, 0), std::min(std::fabs(s[0]), std::fabs(s[1])) / 2);
    const double x0 = p[0] - s[0] / 2, x1 = p[0] + s[0] / 2, y0 = p[1] - s[1] / 2, y1 = p[1] + s[1] / 2;
    BezPath b;
    b.closed = true;
    if (r <= 0) {  // lottie-web's order: top right, bottom right, bottom left, top left
        b.v = {{x1, y0}, {x1, y1}, {x0, y1}, {x0, y0}};
    } else {
        const double k = r * kKappa;
        b.v = {{x1, y0 + r}, {x1, y1 - r}, {x1 - r, y1}, {x0 + r, y1}, {x0, y1 - r}, {x0, y0 + r}, {x0 + r, y0}, {x1 - r, y0}};
        // Corner arcs: from (x1, y1 - r) to (x1 - r, y1), and so on around.
        b.i = {{0, -k}, {0, 0}, {k, 0}, {0, 0}, {0, k}, {0, 0}, {-k, 0}, {0, 0}};
        b.o = {{0, 0}, {0, k}, {0, 0}, {-k, 0}, {0, 0}, {0, -k}, {0, 0}, {k, 0}};
    }
    b.i.resize(b.v.size());
    b.o.resize(b.v.size());
    if (reversed(it)) reverse(b);
    return b;
}

BezPath ellipse(Ctx& c, const Value& it, double t) {
    auto p = prop(c, it.find("p"), t, {0, 0});
    auto s = prop(c, it.find("s"), t, {0, 0});
    p.resize(2);
    s.resize(2);
    const double rx = s[0] / 2, ry = s[1] / 2, kx = rx * kKappa, ky = ry * kKappa;
    BezPath b;
    b.closed = true;
    // lottie-web: top, right, bottom, left (clockwise on screen); d = 3 runs the other way.
    b.v = {{p[0], p[1] - ry}, {p[0] + rx, p[1]}, {p[0], p[1] + ry}, {p[0] - rx, p[1]}};
    b.i = {{-kx, 0}, {0, -ky}, {kx, 0}, {0, ky}};
    b.o = {{kx, 0}, {0, ky}, {-kx, 0}, {0, -ky}};
    if (reversed(it)) reverse(b);
    return b;
}

BezPath polystar(Ctx& c, const Value& it, double t) {
    auto p = prop(c, it.find("p"), t, {0, 0});
    p.resize(2);
    const Value* sy = it.find("sy");  // a plain number (1 star, 2 polygon), or in some files a property
    const bool star = (sy && sy->is_number() ? sy->number : prop1(c, sy, t, 1)) != 2;
    const double pts = std::floor(prop1(c, it.find("pt"), t, 5));
    const int n = int(std::clamp(pts, 0.0, 10000.0));
    const double rot = prop1(c, it.find("r"), t, 0) * M_PI / 180;
    const double orad = prop1(c, it.find("or"), t, 0), ors = prop1(c, it.find("os"), t, 0) / 100;
    const double irad = star ? prop1(c, it.find("ir"), t, 0) : 0, irs = star ? prop1(c, it.find("is"), t, 0) / 100 : 0;
    const double dir = reversed(it) ? -1 : 1;
    BezPath b;
    b.closed = true;
    const int count = star ? 2 * n : n;
    const double step = star ? M_PI / n : 2 * M_PI / n;
    double ang = -M_PI / 2 + rot;
    for (int k = 0; k < count; ++k) {
        const bool outer = !star || k % 2 == 0;
        const double rad = outer ? orad : irad, round = outer ? ors : irs;
        const double perim = 2 * M_PI * rad / (star ? 2 * n : 4 * n);
        const double x = rad * std::cos(ang), y = rad * std::sin(ang);
        const double len = std::hypot(x, y);
        const double ox = len ? y / len : 0, oy = len ? -x / len : 0;
        b.v.push_back({x + p[0], y + p[1]});
        b.i.push_back({ox * perim * round * dir, oy * perim * round * dir});
        b.o.push_back({-ox * perim * round * dir, -oy * perim * round * dir});
        ang += step * dir;
    }
    return b;
}

// Distance of q from the line through a, b (from a when a == b).
double line_dist(Point q, Point a, Point b) {
    const double dx = b.x - a.x, dy = b.y - a.y, l = std::hypot(dx, dy);
    if (l == 0) return std::hypot(q.x - a.x, q.y - a.y);
    return std::fabs((q.x - a.x) * dy - (q.y - a.y) * dx) / l;
}

// Appends the cubic's points after p0 (its control polygon within `tol` of each chord: the
// curve lies in the hull, so every point of it is within `tol` of the polyline).
void subdivide(Point p0, Point p1, Point p2, Point p3, double tol, int depth, std::vector<Point>& out) {
    if (depth >= 18 || std::max(line_dist(p1, p0, p3), line_dist(p2, p0, p3)) <= tol) {
        out.push_back(p3);
        return;
    }
    auto mid = [](Point a, Point b) { return Point{(a.x + b.x) / 2, (a.y + b.y) / 2}; };
    const Point a = mid(p0, p1), b = mid(p1, p2), cc = mid(p2, p3), d = mid(a, b), e = mid(b, cc), f = mid(d, e);
    subdivide(p0, a, d, f, tol, depth + 1, out);
    subdivide(f, e, cc, p3, tol, depth + 1, out);
}

}  // namespace

bool shape_paths(Ctx& c, const Value& item, double t, std::vector<BezPath>& out) {
    const Value* ty = item.find("ty");
    const std::string type = ty && ty->is_string() ? ty->text : "";
    if (type == "sh") {
        BezPath p;
        if (!shape_value(c, item.find("ks"), t, p)) return c.ok();
        if (reversed(item)) reverse(p);
        out.push_back(std::move(p));
    } else if (type == "rc") {
        out.push_back(rect(c, item, t));
    } else if (type == "el") {
        out.push_back(ellipse(c, item, t));
    } else if (type == "sr") {
        out.push_back(polystar(c, item, t));
    }
    return c.ok();
}

bool flatten(Ctx& c, const BezPath& p, const Mat2x3& m, std::vector<Point>& out) {
    out.clear();
    const size_t n = p.v.size();
    if (!n) return true;
    auto map = [&](Vec v) { Point r; m.apply(v.x, v.y, r.x, r.y); return r; };
    out.push_back(map(p.v[0]));
    const size_t segs = p.closed ? n : n - 1;
    for (size_t j = 0; j < segs; ++j) {
        const Vec& a = p.v[j];
        const Vec& b = p.v[(j + 1) % n];
        const Point p0 = map(a), p3 = map(b);
        const Vec o = p.o[j], i = p.i[(j + 1) % n];
        if (o.x == 0 && o.y == 0 && i.x == 0 && i.y == 0) out.push_back(p3);
        else subdivide(p0, map({a.x + o.x, a.y + o.y}), map({b.x + i.x, b.y + i.y}), p3, c.tolerance, 0, out);
        if (out.size() > c.bounds.max_path_vertices)
            return c.fail("a path flattens to more than " + std::to_string(c.bounds.max_path_vertices) + " points");
    }
    if (p.closed && out.size() > 1) out.pop_back();  // the closing point repeats the first
    c.points_done += out.size();
    if (c.points_done > c.bounds.max_total_points)
        return c.fail("the animation needs more than " + std::to_string(c.bounds.max_total_points) +
                      " flattened points over its frames (evaluation work limit)");
    return true;
}

namespace {

double length(const Poly& p) {
    double l = 0;
    const size_t n = p.pts.size(), segs = p.closed ? n : (n ? n - 1 : 0);
    for (size_t j = 0; j < segs; ++j) l += std::hypot(p.pts[(j + 1) % n].x - p.pts[j].x, p.pts[(j + 1) % n].y - p.pts[j].y);
    return l;
}

// The open piece of p between arc lengths a and b (0 <= a <= b <= length).
Poly piece(const Poly& p, double a, double b) {
    Poly r;
    const size_t n = p.pts.size(), segs = p.closed ? n : n - 1;
    double s = 0;
    for (size_t j = 0; j < segs; ++j) {
        const Point& p0 = p.pts[j];
        const Point& p1 = p.pts[(j + 1) % n];
        const double l = std::hypot(p1.x - p0.x, p1.y - p0.y);
        const double e = s + l;
        auto at = [&](double d) { const double f = l > 0 ? (d - s) / l : 0; return Point{p0.x + f * (p1.x - p0.x), p0.y + f * (p1.y - p0.y)}; };
        if (e >= a && s <= b) {
            if (r.pts.empty()) r.pts.push_back(at(std::max(a, s)));
            r.pts.push_back(at(std::min(b, e)));
        }
        s = e;
    }
    return r;
}

}  // namespace

void trim(std::vector<Poly>& polys, double start, double end, double offset, bool joined) {
    start = std::clamp(start, 0.0, 1.0);
    end = std::clamp(end, 0.0, 1.0);
    if (start > end) std::swap(start, end);
    if (end - start >= 1) return;
    double s = start + offset - std::floor(start + offset);
    double e = s + (end - start);
    std::vector<double> lens;
    double total = 0;
    for (const Poly& p : polys) { lens.push_back(length(p)); total += lens.back(); }
    std::vector<Poly> out;
    // Ranges in fractions: [s, e] and, when it wraps, [0, e - 1].
    auto cut = [&](const Poly& p, double base, double len, double whole) {
        for (auto [ra, rb] : {std::pair{s, std::min(e, 1.0)}, std::pair{0.0, e > 1 ? e - 1 : 0.0}}) {
            const double a = ra * whole - base, b = rb * whole - base;
            if (rb <= ra || b <= 0 || a >= len) continue;
            Poly q = piece(p, std::max(a, 0.0), std::min(b, len));
            if (q.pts.size() >= 2) out.push_back(std::move(q));
        }
    };
    double base = 0;
    for (size_t k = 0; k < polys.size(); ++k) {
        if (joined) cut(polys[k], base, lens[k], total);
        else cut(polys[k], 0, lens[k], lens[k]);
        base += lens[k];
    }
    polys = std::move(out);
}

bool dash(std::vector<Poly>& polys, const std::vector<double>& pattern, double offset, size_t max_dashes) {
    double period = 0;
    for (double d : pattern) period += std::max(d, 0.0);
    if (pattern.empty() || period <= 0) return true;
    double total = 0;
    for (const Poly& p : polys) total += length(p);
    // Bounded before any is made: a tiny pattern on a long path would make millions.
    if (!(total / period * double(pattern.size()) / 2 <= double(max_dashes))) return false;
    std::vector<Poly> out;
    for (const Poly& p : polys) {
        const double len = length(p);
        // Dashes start `offset` into the pattern, as a canvas's lineDashOffset does.
        double pos = -std::fmod(std::fmod(offset, period) + period, period);
        size_t k = 0;
        while (pos < len) {
            const double d = std::max(pattern[k % pattern.size()], 0.0);
            if (k % 2 == 0 && pos + d > 0) {
                Poly q = piece(p, std::max(pos, 0.0), std::min(pos + d, len));
                if (q.pts.size() >= 2) out.push_back(std::move(q));
            }
            pos += d;
            ++k;
        }
    }
    polys = std::move(out);
    return true;
}

}  // namespace spt::import::lottie
