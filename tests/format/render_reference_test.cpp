// An independent, deliberately slow implementation of SPEC section 8, written from the draft
// text (format/SPEC.md section 8) without any code shared with format/src: every pixel
// of the canvas is evaluated for every stroke with the formulas as written (direct floor
// divisions, 128-bit products where the text allows big integers). The fast renderer must
// produce identical canvases on thousands of random strokes.
#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "format/render_test_util.hpp"

namespace {

using namespace spt_test;
using i64 = int64_t;
using i128 = __int128;

i64 fdiv(i128 n, i128 d) {  // floor(n / d), any signs
    i128 q = n / d;
    if (n % d != 0 && ((n < 0) != (d < 0))) --q;
    return i64(q);
}

struct Ref {
    const spt::Header& h;
    const std::vector<spt::Template>& t;

    // 8.4 template coverage at (U, V), Q16.
    int cov_template(const spt::Template& tp, i64 U, i64 V) const {
        if (U < -131072 || U > 131072 || V < -131072 || V > 131072) return 0;
        switch (tp.kind) {
            case spt::TemplateKind::Ellipse: return U * U + V * V <= i64(65536) * 65536 ? 255 : 0;
            case spt::TemplateKind::Rectangle: return (U >= -65536 && U <= 65536 && V >= -65536 && V <= 65536) ? 255 : 0;
            case spt::TemplateKind::Triangle: return (U >= -65536 && V >= -65536 && U + V <= 0) ? 255 : 0;
            case spt::TemplateKind::Bitmap: break;
        }
        const i64 w = tp.width, hh = tp.height;
        const i64 sx = fdiv(i128(U + 65536) * w, 512), sy = fdiv(i128(V + 65536) * hh, 512);
        if (sx < 0 || sx >= 256 * w || sy < 0 || sy >= 256 * hh) return 0;
        const i64 qx = sx - 128, qy = sy - 128;
        const i64 ix = fdiv(qx, 256), iy = fdiv(qy, 256);
        const i64 fx = qx - 256 * ix, fy = qy - 256 * iy;
        auto px = [&](i64 i, i64 j) {
            i = std::min(std::max(i, i64(0)), w - 1);
            j = std::min(std::max(j, i64(0)), hh - 1);
            return i64(tp.pixels[size_t(j * w + i)]);
        };
        const i64 top = px(ix, iy) * (256 - fx) + px(ix + 1, iy) * fx;
        const i64 bot = px(ix, iy + 1) * (256 - fx) + px(ix + 1, iy + 1) * fx;
        return int(fdiv(top * (256 - fy) + bot * fy + 32768, 65536));
    }

    // 8.2 supersampling: N x N samples at 1/256-pixel offsets o_k = floor((2k + 1) * 128 / N),
    // coverage round(255 * inside / N^2), every sample through the same 8.4 test.
    static i64 offset(i64 k, i64 n) { return (2 * k + 1) * 128 / n; }
    static int supersampled(i64 n, const std::function<bool(i64, i64)>& inside) {
        i64 count = 0;
        for (i64 q = 0; q < n; ++q)
            for (i64 p = 0; p < n; ++p) count += inside(offset(p, n), offset(q, n));
        return int((255 * count + n * n / 2) / (n * n));
    }

    // Coverage of a stroke at canvas pixel (x, y).
    int coverage(const spt::Stroke& s, i64 x, i64 y) const {
        if (s.kind == spt::StrokeKind::Stamp) {
            const auto& st = s.stamp;
            const i64 W = h.sets[st.set].width, H = h.sets[st.set].height;
            const i64 C = h.orientations[st.orient].cos_q14, S = h.orientations[st.orient].sin_q14;
            const i64 i = x - fdiv(st.x, 16), j = y - fdiv(st.y, 16);
            const i64 rx = (W * std::abs(C) + H * std::abs(S)) / 32768 + 1;
            const i64 ry = (W * std::abs(S) + H * std::abs(C)) / 32768 + 1;
            if (i < -rx || i > rx || j < -ry || j > ry) return 0;
            if (const i64 n = t[st.tmpl].supersample; n > 1)
                return supersampled(n, [&](i64 op, i64 oq) {
                    const i64 ii = 256 * i + op - 128, jj = 256 * j + oq - 128;
                    return cov_template(t[st.tmpl], fdiv(8 * (ii * C + jj * S), 256 * W), fdiv(8 * (jj * C - ii * S), 256 * H)) == 255;
                });
            const i64 U = fdiv(8 * (i * C + j * S), W), V = fdiv(8 * (j * C - i * S), H);
            return cov_template(t[st.tmpl], U, V);
        }
        if (s.kind == spt::StrokeKind::Affine) {
            const auto& af = s.affine;
            const i64 det = i64(af.a) * af.d - i64(af.b) * af.c;
            if (det == 0) return 0;
            const i64 X = 16 * x + 8, Y = 16 * y + 8;
            const i64 n = t[af.tmpl].supersample;
            const i64 grow = n > 1 ? 8 : 0;
            const i64 ex = std::abs(i64(af.a)) + std::abs(i64(af.b)) + grow, ey = std::abs(i64(af.c)) + std::abs(i64(af.d)) + grow;
            if (X < af.tx - ex || X > af.tx + ex || Y < af.ty - ey || Y > af.ty + ey) return 0;
            if (n > 1)
                return supersampled(n, [&](i64 op, i64 oq) {
                    const i64 sx = 256 * x + op - 16 * i64(af.tx), sy = 256 * y + oq - 16 * i64(af.ty);
                    const i64 U = fdiv(i128(4096) * (i128(af.d) * sx - i128(af.b) * sy), det);
                    const i64 V = fdiv(i128(4096) * (i128(af.a) * sy - i128(af.c) * sx), det);
                    return cov_template(t[af.tmpl], U, V) == 255;
                });
            const i64 dx = X - af.tx, dy = Y - af.ty;
            const i64 U = fdiv(i128(65536) * (i128(af.d) * dx - i128(af.b) * dy), det);
            const i64 V = fdiv(i128(65536) * (i128(af.a) * dy - i128(af.c) * dx), det);
            return cov_template(t[af.tmpl], U, V);
        }
        if (s.kind == spt::StrokeKind::Polygon) {
            // SPEC 8.8, literally: in 1/256 px, every edge tested at every sample.
            const auto& P = s.polygon.points;
            auto inside = [&](i64 X, i64 Y) {
                i64 w = 0;
                for (size_t k = 0; k < P.size(); ++k) {
                    const auto& a = P[k];
                    const auto& b = P[(k + 1) % P.size()];
                    if (a.y == b.y) continue;
                    const bool down = b.y > a.y;
                    const i64 xa = 16 * i64(down ? a.x : b.x), ya = 16 * i64(down ? a.y : b.y);
                    const i64 xb = 16 * i64(down ? b.x : a.x), yb = 16 * i64(down ? b.y : a.y);
                    if (ya <= Y && Y < yb && i128(X - xa) * (yb - ya) >= i128(xb - xa) * (Y - ya)) w += down ? 1 : -1;
                }
                return w != 0;
            };
            const i64 n = s.polygon.supersample;
            if (n == 0) return inside(256 * x + 128, 256 * y + 128) ? 255 : 0;
            return supersampled(n, [&](i64 ox, i64 oy) { return inside(256 * x + ox, 256 * y + oy); });
        }
        // SPEC 8.5, literally: every segment tested at every sample (1/256 px).
        const auto& pts = s.curve.points;
        auto inside = [&](i64 Xs, i64 Ys) {
            for (size_t k = 0; k < pts.size(); ++k) {
                const auto& p0 = pts[k];
                const auto& p1 = pts[std::min(k + 1, pts.size() - 1)];
                if (k + 1 == pts.size() && pts.size() > 1) break;
                const i64 dx = i64(p1.x) - p0.x, dy = i64(p1.y) - p0.y, qx = Xs - 16 * i64(p0.x), qy = Ys - 16 * i64(p0.y);
                const i128 L = i128(dx) * dx + i128(dy) * dy, t = i128(qx) * dx + i128(qy) * dy;
                i64 T = 0;
                if (L > 0 && t >= 16 * L) T = 1 << 24;
                else if (L > 0 && t > 0) T = fdiv(t * (1 << 20), L);
                const i128 ex = i128(16) * qx - fdiv(i128(T) * dx, 65536);
                const i128 ey = i128(16) * qy - fdiv(i128(T) * dy, 65536);
                const i128 R = fdiv(i128(p0.width) * (1 << 24) + i128(T) * (i64(p1.width) - i64(p0.width)), 131072);
                if (ex * ex + ey * ey <= R * R) return true;
            }
            return false;
        };
        const i64 n = s.curve.supersample;
        if (n == 0) return inside(256 * x + 128, 256 * y + 128) ? 255 : 0;
        return supersampled(n, [&](i64 ox, i64 oy) { return inside(256 * x + ox, 256 * y + oy); });
    }

    void draw(spt::Canvas& c, const spt::Stroke& s) const {
        const spt::Rgba8 col = s.kind == spt::StrokeKind::Stamp ? s.stamp.color
                             : s.kind == spt::StrokeKind::Affine ? s.affine.color
                             : s.kind == spt::StrokeKind::Curve ? s.curve.color : s.polygon.color;
        for (uint32_t y = 0; y < c.height; ++y)
            for (uint32_t x = 0; x < c.width; ++x) {
                const i64 al = (i64(coverage(s, x, y)) * col.a + 127) / 255;
                uint8_t* p = &c.rgb[(size_t(y) * c.width + x) * 3];
                const uint8_t src[3] = {col.r, col.g, col.b};
                for (int k = 0; k < 3; ++k) p[k] = uint8_t((p[k] * (255 - al) + src[k] * al + 127) / 255);
            }
    }
};

// Random strokes of every kind, size, alpha and position, many partly off the canvas.
std::vector<spt::Stroke> random_strokes(std::mt19937& rng, const spt::Header& h, size_t ntemplates, int n) {
    auto U = [&](i64 lo, i64 hi) { return std::uniform_int_distribution<i64>(lo, hi)(rng); };
    const i64 W = h.width * 16, H = h.height * 16;
    std::vector<spt::Stroke> v;
    for (int i = 0; i < n; ++i) {
        const spt::Rgba8 col{uint8_t(U(0, 255)), uint8_t(U(0, 255)), uint8_t(U(0, 255)),
                             uint8_t(U(0, 3) == 0 ? 255 : U(0, 255))};
        const int kind = int(U(0, 9));
        if (kind < 5) {
            v.push_back(stamp(uint8_t(U(0, i64(h.sets.size()) - 1)), uint8_t(U(0, i64(ntemplates) - 1)),
                              uint8_t(U(0, i64(h.orientations.size()) - 1)), int32_t(U(-200, W + 200)),
                              int32_t(U(-200, H + 200)), col));
        } else if (kind < 8) {
            const i64 sc = U(0, 3) == 0 ? 600 : 160;
            int32_t m[4];
            for (int32_t& e : m) e = int32_t(U(-sc, sc));
            if (U(0, 20) == 0) { m[2] = m[0] * 2; m[3] = m[1] * 2; }  // singular now and then
            v.push_back(affine(uint8_t(U(0, i64(ntemplates) - 1)), int32_t(U(-300, W + 300)),
                               int32_t(U(-300, H + 300)), m[0], m[1], m[2], m[3], col));
        } else {
            std::vector<spt::CurvePoint> pts;
            i64 x = U(-100, W + 100), y = U(-100, H + 100);
            const int np = int(U(1, 5));
            for (int k = 0; k < np; ++k) {
                pts.push_back({int32_t(x), int32_t(y), uint32_t(U(0, 160))});
                x += U(-300, 300);
                y += U(-300, 300);
                if (U(0, 6) == 0) { x = pts.back().x; y = pts.back().y; }  // repeated points
            }
            v.push_back(curve(std::move(pts), col));
        }
    }
    return v;
}

std::vector<spt::Template> test_templates(std::mt19937& rng) {
    std::vector<spt::Template> t = {analytic(spt::TemplateKind::Ellipse), analytic(spt::TemplateKind::Rectangle),
                                    analytic(spt::TemplateKind::Triangle)};
    for (auto [w, hh] : {std::pair{1, 1}, {7, 3}, {16, 16}, {60, 60}}) {
        std::vector<uint8_t> px(size_t(w * hh));
        for (auto& p : px) p = uint8_t(rng() % 4 == 0 ? 0 : rng() % 256);
        t.push_back(bitmap(uint16_t(w), uint16_t(hh), std::move(px)));
    }
    return t;
}

// `rounds` rounds of `count` random strokes from the background: each stroke drawn alone by the
// fast renderer equals the reference's draw (the first that disagrees is named), and each round's
// render equals the reference's canvas. Adds the strokes checked to `strokes`.
void expect_rounds_equal_reference(std::mt19937& rng, const spt::Renderer& r, const Ref& ref, int rounds, int count,
                                   int& strokes) {
    for (int round = 0; round < rounds; ++round) {
        const auto v = random_strokes(rng, ref.h, ref.t.size(), count);
        spt::Canvas fast, slow(ref.h.width, ref.h.height, ref.h.background);
        ASSERT_TRUE(r.render(fast, v).ok());
        for (size_t i = 0; i < v.size(); ++i) {
            spt::Canvas one = slow;
            ref.draw(slow, v[i]);
            ASSERT_TRUE(r.draw(one, v[i]).ok());
            ASSERT_EQ(one.rgb, slow.rgb) << "round " << round << " stroke " << i << " kind " << int(v[i].kind);
        }
        ASSERT_EQ(fast.rgb, slow.rgb);
        strokes += int(v.size());
    }
}

// One list: each stroke drawn alone by the fast renderer equals the reference's draw (the first
// that disagrees is named, with its kind and grid), and the tiled render of the list equals it.
void expect_list_equals_reference(const spt::Renderer& r, const Ref& ref, const std::vector<spt::Stroke>& v,
                                  const std::string& what) {
    spt::Canvas fast, slow(ref.h.width, ref.h.height, ref.h.background);
    ASSERT_TRUE(r.render(fast, v).ok());
    for (size_t i = 0; i < v.size(); ++i) {
        spt::Canvas one = slow;
        ref.draw(slow, v[i]);
        ASSERT_TRUE(r.draw(one, v[i]).ok());
        ASSERT_EQ(one.rgb, slow.rgb) << what << " stroke " << i << " kind " << int(v[i].kind) << " grid "
                                     << int(v[i].kind == spt::StrokeKind::Curve ? v[i].curve.supersample : v[i].polygon.supersample);
    }
    ASSERT_EQ(fast.rgb, slow.rgb) << what;
}

TEST(RenderReference, FastRendererEqualsIndependentReference) {
    std::mt19937 rng(20240607);
    const auto templates = test_templates(rng);
    auto hd = make_header(48, 36, {{40, 17}, {16, 6}, {9, 9}, {4, 1}, {1, 1}, {3, 30}}, 8);
    hd.background = {12, 200, 77};
    // A rogue but legal table entry: a bit longer than unit, and negative components.
    hd.orientations.push_back({-16385, -7});
    hd.orientations.push_back({11585, -11585});
    auto r = make_renderer(hd, templates);
    const Ref ref{hd, templates};
    int strokes = 0;
    expect_rounds_equal_reference(rng, *r, ref, 12, 300, strokes);
    EXPECT_EQ(strokes, 3600);
}

// Polygons (SPEC 8.8): random outlines, convex and self-intersecting, with repeated vertices,
// horizontal edges, vertices on pixel centres (edge-rule ties) and off-canvas parts, at every
// grid N; single draws and the tiled renderer against the reference.
TEST(RenderReference, PolygonsEqualReference) {
    std::mt19937 rng(777);
    auto U = [&](i64 lo, i64 hi) { return std::uniform_int_distribution<i64>(lo, hi)(rng); };
    std::vector<spt::Template> templates = {analytic(spt::TemplateKind::Ellipse)};
    auto hd = make_header(40, 30, {{8, 8}}, 4);
    auto r = make_renderer(hd, templates);
    const Ref ref{hd, templates};
    for (int round = 0; round < 6; ++round) {
        std::vector<spt::Stroke> v;
        for (int i = 0; i < 60; ++i) {
            spt::PolygonStroke pg;
            pg.color = {uint8_t(U(0, 255)), uint8_t(U(0, 255)), uint8_t(U(0, 255)), uint8_t(U(0, 2) ? 255 : U(1, 254))};
            const i64 nn = U(0, 3);
            pg.supersample = uint8_t(nn == 0 || nn == 1 ? 0 : nn == 2 ? U(2, 5) : 16);
            const int n = int(U(3, 9));
            const bool lattice = U(0, 1);  // on pixel centres / corners: ties everywhere
            for (int k = 0; k < n; ++k) {
                i64 x = U(-120, 16 * 40 + 120), y = U(-120, 16 * 30 + 120);
                if (lattice) { x = 8 * (x / 8); y = 8 * (y / 8); }
                if (k && U(0, 7) == 0) { x = pg.points.back().x; y = pg.points.back().y; }       // repeated
                else if (k && U(0, 7) == 0) y = pg.points.back().y;                             // horizontal
                pg.points.push_back({int32_t(x), int32_t(y)});
            }
            v.push_back(spt::Stroke::make_polygon(std::move(pg)));
        }
        ASSERT_NO_FATAL_FAILURE(expect_list_equals_reference(*r, ref, v, "round " + std::to_string(round)));
    }
    // A square on pixel corners covers exactly its pixels; two halves of it cut along a
    // diagonal cover every centre once (the edge ownership rule).
    spt::Canvas c(hd.width, hd.height, {0, 0, 0});
    spt::PolygonStroke a, b;
    a.color = b.color = {100, 100, 100, 255};
    a.points = {{16 * 2, 16 * 2}, {16 * 12, 16 * 2}, {16 * 2, 16 * 12}};
    b.points = {{16 * 12, 16 * 2}, {16 * 12, 16 * 12}, {16 * 2, 16 * 12}};
    spt::Canvas twice = c;
    ASSERT_TRUE(r->draw(c, spt::Stroke::make_polygon(a)).ok());
    ASSERT_TRUE(r->draw(c, spt::Stroke::make_polygon(b)).ok());
    a.color = b.color = {50, 50, 50, 128};
    ASSERT_TRUE(r->draw(twice, spt::Stroke::make_polygon(a)).ok());
    ASSERT_TRUE(r->draw(twice, spt::Stroke::make_polygon(b)).ok());
    for (uint32_t y = 0; y < hd.height; ++y)
        for (uint32_t x = 0; x < hd.width; ++x) {
            const bool in = x >= 2 && x < 12 && y >= 2 && y < 12;
            EXPECT_EQ(c.rgb[(size_t(y) * hd.width + x) * 3], in ? 100 : 0) << x << "," << y;
            EXPECT_EQ(twice.rgb[(size_t(y) * hd.width + x) * 3], in ? 25 : 0) << x << "," << y;  // blended once
        }
}

// Anti-aliased curves (format 1.4, SPEC 8.5 on the samples of 8.8): random polylines of every
// width from hairlines to blobs, with repeated points, one-point discs, growing and shrinking
// widths and off-canvas parts, at every grid, against the literal reference. The rasterizer
// classifies pixels by their centre's distance first; this is what checks that shortcut exact.
TEST(RenderReference, AntiAliasedCurvesEqualReference) {
    std::mt19937 rng(1404);
    auto U = [&](i64 lo, i64 hi) { return std::uniform_int_distribution<i64>(lo, hi)(rng); };
    std::vector<spt::Template> templates = {analytic(spt::TemplateKind::Ellipse)};
    auto hd = make_header(40, 30, {{8, 8}}, 4);
    auto r = make_renderer(hd, templates);
    const Ref ref{hd, templates};
    int partial = 0;  // pixels of fractional coverage seen: the grid must matter
    for (int round = 0; round < 6; ++round) {
        std::vector<spt::Stroke> v;
        for (int i = 0; i < 50; ++i) {
            spt::CurveStroke cv;
            cv.color = {uint8_t(U(0, 255)), uint8_t(U(0, 255)), uint8_t(U(0, 255)), uint8_t(U(0, 2) ? 255 : U(1, 254))};
            const i64 g = U(0, 4);
            cv.supersample = uint8_t(g == 0 ? 0 : g == 1 ? 2 : g == 2 ? 4 : g == 3 ? U(3, 7) : 16);
            const int n = int(U(1, 6));
            const i64 wide = U(0, 3) == 0 ? 200 : 60;
            i64 x = U(-100, 16 * 40 + 100), y = U(-100, 16 * 30 + 100);
            for (int k = 0; k < n; ++k) {
                cv.points.push_back({int32_t(x), int32_t(y), uint32_t(U(0, wide))});
                x += U(-250, 250);
                y += U(-250, 250);
                if (U(0, 6) == 0) { x = cv.points.back().x; y = cv.points.back().y; }  // repeated
                else if (U(0, 6) == 0) y = cv.points.back().y;                        // horizontal
            }
            v.push_back(spt::Stroke::make_curve(std::move(cv)));
        }
        ASSERT_NO_FATAL_FAILURE(expect_list_equals_reference(*r, ref, v, "round " + std::to_string(round)));
        for (const spt::Stroke& st : v)
            if (st.curve.supersample)
                for (uint32_t y = 0; y < hd.height; ++y)
                    for (uint32_t x = 0; x < hd.width; ++x) {
                        const int c = ref.coverage(st, x, y);
                        partial += c > 0 && c < 255;
                    }
    }
    EXPECT_GT(partial, 1000);
    // A grid-0 curve is the format 1.3 curve: its centre samples give the old rule's pixels
    // (a horizontal 2 px line through pixel centres covers rows 9 and 10 only).
    spt::CurveStroke line;
    line.color = {0, 0, 0, 255};
    line.points = {{16 * 5, 16 * 10, 32}, {16 * 30, 16 * 10, 32}};
    spt::Canvas c(hd.width, hd.height, {255, 255, 255});
    ASSERT_TRUE(r->draw(c, spt::Stroke::make_curve(line)).ok());
    for (uint32_t y = 0; y < hd.height; ++y) EXPECT_EQ(c.rgb[(size_t(y) * hd.width + 20) * 3], y == 9 || y == 10 ? 0 : 255) << y;
    // The same line at grid 4 ends in round caps: its end pixels are partly covered.
    line.supersample = 4;
    spt::Canvas aa(hd.width, hd.height, {255, 255, 255});
    ASSERT_TRUE(r->draw(aa, spt::Stroke::make_curve(line)).ok());
    const uint8_t end = aa.rgb[(size_t(10) * hd.width + 30) * 3];
    EXPECT_GT(end, 0);
    EXPECT_LT(end, 255);
}

// Stamps too big for the footprint cache (render_impl.hpp: kMaxFootprintBytes) are drawn through
// their inverse map instead; the pixels must not change.
TEST(RenderReference, UncachedHugeStampsEqualReference) {
    std::mt19937 rng(11);
    const auto templates = test_templates(rng);
    auto hd = make_header(64, 40, {{4096, 4096}, {4096, 700}, {9, 5}}, 8);
    auto r = make_renderer(hd, templates);
    const Ref ref{hd, templates};
    spt::Canvas slow(hd.width, hd.height, hd.background);
    std::vector<spt::Stroke> v;
    for (int i = 0; i < 40; ++i) {
        const auto U = [&](int64_t lo, int64_t hi) { return std::uniform_int_distribution<int64_t>(lo, hi)(rng); };
        v.push_back(stamp(uint8_t(U(0, 2)), uint8_t(U(0, int64_t(templates.size()) - 1)), uint8_t(U(0, 7)),
                          int32_t(U(-40000, 40000)), int32_t(U(-40000, 40000)),
                          {uint8_t(U(0, 255)), uint8_t(U(0, 255)), uint8_t(U(0, 255)), uint8_t(U(1, 255))}));
        ref.draw(slow, v.back());
    }
    spt::Canvas fast;
    ASSERT_TRUE(r->render(fast, v).ok());
    EXPECT_EQ(fast.rgb, slow.rgb);
    EXPECT_LT(r->footprint_cache_bytes(), size_t(32) << 20);  // the 4096 x 4096 ones not stored
}

// Supersampled analytic templates (SPEC 3.2, 8.2) for several grids, stamps and affine strokes.
TEST(RenderReference, SupersampledTemplatesEqualReference) {
    std::mt19937 rng(316);
    std::vector<spt::Template> templates;
    for (int n : {2, 3, 4, 8, 16, 5})
        for (auto k : {spt::TemplateKind::Ellipse, spt::TemplateKind::Rectangle, spt::TemplateKind::Triangle}) {
            templates.push_back(analytic(k));
            templates.back().supersample = uint8_t(n);
        }
    templates.push_back(analytic(spt::TemplateKind::Ellipse));  // and one point-sampled
    auto hd = make_header(40, 30, {{24, 11}, {5, 5}, {1, 2}}, 8);
    auto r = make_renderer(hd, templates);
    const Ref ref{hd, templates};
    int strokes = 0;
    expect_rounds_equal_reference(rng, *r, ref, 4, 150, strokes);
    if (::testing::Test::HasFatalFailure()) return;
    // An axis-aligned half-pixel edge gives exactly half coverage.
    spt::AffineStroke a;
    a.tmpl = 1; a.tx = 16 * 10; a.ty = 16 * 10 + 8; a.a = 16 * 4; a.d = 16 * 4; a.color = {255, 255, 255, 255};
    spt::Mask m;
    ASSERT_TRUE(r->stroke_mask(spt::Stroke::make_affine(a), m).ok());  // template 1: rectangle, N = 2
    // Left edge at x = 6.0 px: pixel 6 fully inside, pixel 5 has no sample inside.
    const auto at = [&](int x, int y) { return int(m.a[size_t((y - m.y0) * int(m.w) + (x - m.x0))]); };
    EXPECT_EQ(at(6, 10), 255);
    EXPECT_EQ(at(5, 10), 0);
    // Top edge at y = 6.5 px: in pixel 6 one of the two sample rows is inside.
    EXPECT_EQ(at(8, 6), 128);
}

TEST(RenderReference, RenderingIsDeterministic) {
    std::mt19937 rng(7);
    const auto templates = test_templates(rng);
    auto hd = make_header(97, 61, {{30, 12}, {8, 4}, {2, 2}}, 16);
    const auto v = random_strokes(rng, hd, templates.size(), 3000);
    auto r1 = make_renderer(hd, templates), r2 = make_renderer(hd, templates);
    spt::Canvas a, b, c;
    ASSERT_TRUE(r1->render(a, v).ok());
    ASSERT_TRUE(r2->render(b, v).ok());
    ASSERT_TRUE(r1->render(c, v).ok());  // warm cache, same answer
    EXPECT_EQ(a.rgb, b.rgb);
    EXPECT_EQ(a.rgb, c.rgb);
}

}  // namespace
