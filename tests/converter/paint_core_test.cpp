// Painter building blocks: colour estimation and exact error change, candidate randomness,
// stroke sets, built-in templates, edge detection and orientation fields.
#include <gtest/gtest.h>

#include <cmath>

#include "paint/orientation.hpp"
#include "paint/painter.hpp"
#include "paint/rng.hpp"
#include "paint/stamp_score.hpp"

using namespace spt;
using namespace spt::paint;

namespace {

int64_t sse(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    int64_t e = 0;
    for (size_t i = 0; i < a.size(); ++i) e += (int(a[i]) - int(b[i])) * (int(a[i]) - int(b[i]));
    return e;
}

Mask square_mask(uint32_t side, uint8_t alpha) {
    Mask m;
    m.x0 = -int32_t(side / 2);
    m.y0 = -int32_t(side / 2);
    m.w = m.h = side;
    m.a.assign(size_t(side) * side, alpha);
    return m;
}

}  // namespace

TEST(PaintScore, OpaqueColourIsTheModelMeanUnderTheStroke) {
    const uint32_t W = 8, H = 8;
    std::vector<uint8_t> model(W * H * 3), canvas(W * H * 3, 255);
    for (size_t i = 0; i < W * H; ++i) { model[i * 3] = uint8_t(i % 2 ? 100 : 50); model[i * 3 + 1] = 10; model[i * 3 + 2] = 250; }
    const Plane p{W, H, model.data(), canvas.data()};
    const Mask m = square_mask(4, 255);
    const StampScore s = score_stamp(p, m, 4, 4);
    ASSERT_TRUE(s.valid);
    EXPECT_EQ(s.color.r, 75);  // mean of 50 and 100 (round half up)
    EXPECT_EQ(s.color.g, 10);
    EXPECT_EQ(s.color.b, 250);
}

TEST(PaintScore, DeltaIsTheExactErrorChangeOfTheCommit) {
    const uint32_t W = 13, H = 11;
    std::vector<uint8_t> model(W * H * 3), canvas(W * H * 3);
    uint64_t r = 7;
    for (auto& v : model) v = uint8_t(mix64(++r) >> 56);
    for (auto& v : canvas) v = uint8_t(mix64(++r) >> 56);
    Mask m = square_mask(6, 0);
    for (size_t i = 0; i < m.a.size(); ++i) m.a[i] = uint8_t(mix64(++r) >> 56);  // partial coverage
    for (int py : {0, 5, 10})
        for (int px : {0, 6, 12}) {  // centre, and clipped at every border
            std::vector<uint8_t> c = canvas;
            const Plane p{W, H, model.data(), c.data()};
            const StampScore s = score_stamp(p, m, px, py);
            ASSERT_TRUE(s.valid);
            const int64_t before = sse(c, model);
            commit_stamp(p, m, px, py, s.color);
            EXPECT_EQ(sse(c, model) - before, s.delta) << px << "," << py;
        }
}

TEST(PaintScore, PartialCoverageColourMinimisesTheError) {
    // With 50% coverage over a black canvas and a mid-grey model, the best colour overshoots
    // the model (the canvas shows through), which a plain model mean would not do.
    const uint32_t W = 4, H = 4;
    std::vector<uint8_t> model(W * H * 3, 100), canvas(W * H * 3, 0);
    const Plane p{W, H, model.data(), canvas.data()};
    const Mask m = square_mask(4, 128);
    const StampScore s = score_stamp(p, m, 2, 2);
    ASSERT_TRUE(s.valid);
    EXPECT_NEAR(s.color.r, 199, 1);
    // No other colour does better.
    for (int c = 0; c < 256; c += 1) {
        if (c == s.color.r) continue;
        int64_t e_best = 0, e_c = 0;
        for (size_t i = 0; i < W * H; ++i) {
            e_best += (blend8(0, s.color.r, 128) - 100) * (blend8(0, s.color.r, 128) - 100);
            e_c += (blend8(0, uint8_t(c), 128) - 100) * (blend8(0, uint8_t(c), 128) - 100);
        }
        EXPECT_LE(e_best, e_c) << c;
    }
}

TEST(PaintRng, DrawsArePureFunctionsOfSeedSetCounterStream) {
    EXPECT_EQ(rng_draw(5, 2, 1000, RngStream::Position), rng_draw(5, 2, 1000, RngStream::Position));
    EXPECT_NE(rng_draw(5, 2, 1000, RngStream::Position), rng_draw(6, 2, 1000, RngStream::Position));
    EXPECT_NE(rng_draw(5, 2, 1000, RngStream::Position), rng_draw(5, 3, 1000, RngStream::Position));
    EXPECT_NE(rng_draw(5, 2, 1000, RngStream::Position), rng_draw(5, 2, 1000, RngStream::Template));
    // Roughly uniform: 8 bins of 80k draws each within 2%.
    std::vector<int> bins(8, 0);
    for (uint64_t i = 0; i < 80000; ++i) ++bins[rng_below(rng_draw(1, 0, i, RngStream::Template), 8)];
    for (int b : bins) EXPECT_NEAR(b, 10000, 200);
}

TEST(PaintSetupTest, DefaultSetsGoFromLargeToSmall) {
    for (int n : {3, 6, 10}) {
        const auto sets = default_sets(1280, 720, n);
        ASSERT_EQ(int(sets.size()), n);
        for (size_t i = 1; i < sets.size(); ++i) EXPECT_LE(sets[i].width, sets[i - 1].width);
        EXPECT_GT(sets.front().width, 100);
        EXPECT_LE(sets.back().width, 6);
        for (const auto& s : sets) EXPECT_GE(s.width, s.height);
    }
    EXPECT_EQ(default_sets(100, 100, 2).size(), 3u);   // clamped to 3..10
    EXPECT_EQ(default_sets(100, 100, 50).size(), 10u);
}

TEST(PaintSetupTest, BuiltInTemplatesAreTheMeasuredThree) {
    // README.md "Templates": analytic rectangle and ellipse, a 16x16 soft round.
    const auto t = default_templates();
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t[0].name, "rectangle");
    EXPECT_EQ(t[0].kind, TemplateKind::Rectangle);
    EXPECT_EQ(t[2].name, "ellipse");
    EXPECT_EQ(t[2].kind, TemplateKind::Ellipse);
    EXPECT_EQ(t[2].supersample, 4);
    EXPECT_EQ(t[1].name, "soft-round");
    EXPECT_EQ(t[1].kind, TemplateKind::Bitmap);
    EXPECT_EQ(t[1].width, 16);
    EXPECT_EQ(t[1].height, 16);
    ASSERT_EQ(t[1].pixels.size(), 256u);
    uint64_t sum = 0;
    for (uint8_t v : t[1].pixels) sum += v;
    EXPECT_GT(sum, 256u * 255 / 4);  // a brush, not a speck
    EXPECT_EQ(t[1].pixels[0], 0);     // soft: nothing in the corners
    EXPECT_EQ(t[1].pixels[8 * 16 + 8], 255);
}

namespace {

// A step edge through the image centre whose edge line runs along `theta` (image coordinates,
// y down): dark on one side, bright on the other, with mild noise.
std::vector<uint8_t> step_image(uint32_t W, uint32_t H, double theta) {
    std::vector<uint8_t> img(size_t(W) * H * 3);
    const double nx = -std::sin(theta), ny = std::cos(theta);  // normal of the edge line
    uint64_t r = 1;
    for (uint32_t y = 0; y < H; ++y)
        for (uint32_t x = 0; x < W; ++x) {
            const double d = (x - W / 2.0) * nx + (y - H / 2.0) * ny;
            const int v = (d > 0 ? 190 : 60) + int(mix64(++r) % 5) - 2;
            for (int c = 0; c < 3; ++c) img[(size_t(y) * W + x) * 3 + c] = uint8_t(v);
        }
    return img;
}

}  // namespace

TEST(PaintOrientation, StepEdgeGivesTheEdgeDirection) {
    const auto table = default_orientations(8);
    const uint32_t W = 64, H = 64;
    for (int k : {0, 2, 4, 6}) {
        const double theta = k * M_PI / 8;
        const auto img = step_image(W, H, theta);
        const ImageView v{W, H, img.data()};
        const EdgeMap em = multiscale_edges(v);
        size_t edges = 0;
        for (auto e : em.edge) edges += e != 0;
        EXPECT_GT(edges, 40u) << "k=" << k;   // the edge is found...
        EXPECT_LT(edges, 400u) << "k=" << k;  // ...and the noise is not
        for (OrientMode mode : {OrientMode::Edges, OrientMode::Gradient}) {
            const auto field = orientation_field(v, table, mode);
            ASSERT_EQ(field.size(), size_t(W) * H);
            // Edges: near the edge and far from it (the nearest edge decides). Gradient: only
            // near the edge, since far from it the local structure is the noise.
            int good = 0, total = 0;
            for (uint32_t y = 16; y < 48; y += 3)
                for (uint32_t x = 16; x < 48; x += 3) {
                    const double d = (x - W / 2.0) * -std::sin(theta) + (y - H / 2.0) * std::cos(theta);
                    if (mode == OrientMode::Gradient && std::fabs(d) > 4) continue;
                    ++total;
                    good += field[size_t(y) * W + x] == k;
                }
            EXPECT_GE(good, total * 9 / 10) << "k=" << k << " mode=" << int(mode);
        }
    }
    EXPECT_TRUE(orientation_field(ImageView{W, H, step_image(W, H, 0).data()}, table, OrientMode::Random).empty());
}

TEST(PaintOrientation, NearestOrientationIsUndirected) {
    const auto table = default_orientations(8);
    EXPECT_EQ(nearest_orientation(table, 0.0), 0);
    EXPECT_EQ(nearest_orientation(table, M_PI), 0);
    EXPECT_EQ(nearest_orientation(table, M_PI / 2), 4);
    EXPECT_EQ(nearest_orientation(table, -M_PI / 4), 6);
    EXPECT_EQ(nearest_orientation(table, 3 * M_PI / 8 + 0.05), 3);
}
