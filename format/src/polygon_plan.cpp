// The reference encoder's choice of how to code a polygon's outline (SPEC.md 7.4, polygon 5):
// the lattice shift, then the prediction mode (and for the conic mode its rotation and matrix)
// whose bits, measured with a copy of the contexts in their current state, are the fewest.
// Nothing here constrains a decoder: any plan the syntax can express decodes.
#include <cmath>

#include "polygon_plan.hpp"
#include "stroke_stream.hpp"

namespace spt::detail {
namespace {

// A "coder" that only adds up the information cost of the decisions it is given, adapting the
// contexts as the real encoder would.
class BitCounter {
public:
    static constexpr bool kDecoding = false;
    void set_field(Field) {}
    int bit(uint16_t& p, int b) {
        bits_ += bit_cost(b ? 2048u - p : p);
        p = b ? uint16_t(p - (p >> kAdaptShift)) : uint16_t(p + ((2048u - p) >> kAdaptShift));
        return b;
    }
    int direct(int b) { bits_ += 1.0; return b; }
    double bits() const { return bits_; }

private:
    double bits_ = 0;
};

// Above this many vertices the conic matrix is not refined entry by entry (each trial codes the
// whole outline); the least-squares matrix is still tried at every shift.
constexpr size_t kRefineMaxVertices = 4096;

struct Planner {
    const PolygonModels& pm;
    std::vector<PolygonVertex>& pts;  // coded, never modified (the encoder writes nothing back)

    // The bits of the outline coded with `plan` a second time, after the contexts adapted to it
    // once: the cost in a stream of similar polygons. Measuring only the first coding would
    // never pick a mode whose contexts are still fresh (and whose rotation is not yet coded)
    // over one that adapted already, however much cheaper it would become.
    double cost(const PolygonPlan& plan) const {
        PolygonModels copy = pm;
        SyntaxError err;
        BitCounter first, again;
        if (!code_polygon_outline(first, copy, plan, pts, err)) return HUGE_VAL;
        if (!code_polygon_outline(again, copy, plan, pts, err)) return HUGE_VAL;
        return first.bits() + again.bits();
    }

    // The largest shift that divides every vertex offset from P_0 (SPEC.md: canonical).
    uint32_t lattice_shift() const {
        uint32_t shift = 4;
        for (size_t i = 1; i < pts.size(); ++i) {
            const int64_t dx = int64_t(pts[i].x) - pts[0].x, dy = int64_t(pts[i].y) - pts[0].y;
            while (shift > 0 && ((dx | dy) & ((int64_t(1) << shift) - 1)) != 0) --shift;
        }
        return shift;
    }

    // Raises the matrix shift while every entry is a multiple of the next power (canonical).
    static void canonical_matrix(PolygonPlan& p) {
        while (p.matrix_shift < 4) {
            const int64_t mask = (int64_t(1) << (p.matrix_shift + 1)) - 1;
            if ((p.m[0] & mask) || (p.m[1] & mask) || (p.m[2] & mask) || (p.m[3] & mask)) break;
            ++p.matrix_shift;
        }
    }

    // Least squares of the offsets P_i - P_0 (Q4) against unit_i - unit_0, one axis at a time:
    // two independent 2-parameter regressions. False when the units do not span the plane.
    bool fit(const PolygonPlan& p, double m[4]) const {
        std::vector<int64_t> du, dv;
        conic_unit_offsets(p.cs[0], p.cs[1], pts.size(), du, dv);
        double suu = 0, suv = 0, svv = 0, sxu = 0, sxv = 0, syu = 0, syv = 0;
        for (size_t i = 1; i < pts.size(); ++i) {
            const double u = double(du[i]) / double(kConicOne), v = double(dv[i]) / double(kConicOne);
            const double x = double(pts[i].x) - pts[0].x, y = double(pts[i].y) - pts[0].y;
            suu += u * u; suv += u * v; svv += v * v;
            sxu += x * u; sxv += x * v; syu += y * u; syv += y * v;
        }
        const double det = suu * svv - suv * suv;
        if (!(std::fabs(det) > 1e-9 * (suu * svv + 1e-30))) return false;
        m[0] = (sxu * svv - sxv * suv) / det;
        m[1] = (sxv * suu - sxu * suv) / det;
        m[2] = (syu * svv - syv * suv) / det;
        m[3] = (syv * suu - syu * suv) / det;
        for (int k = 0; k < 4; ++k)
            if (!(std::fabs(m[k]) < double(kConicMaxMatrix))) return false;
        return true;
    }

    // The conic plan at its best matrix shift, then refined by single steps of one entry while
    // that saves bits. `best` is updated when the conic mode beats it.
    void try_conic(PolygonPlan& best, double& best_bits) const {
        PolygonPlan p = best;
        p.mode = 2;
        conic_rotation_for(pts.size(), p.cs);
        double ls[4];
        if (!fit(p, ls)) return;
        PolygonPlan cand = p;
        double cand_bits = HUGE_VAL;
        for (uint32_t t = 0; t <= 4; ++t) {
            PolygonPlan q = p;
            q.matrix_shift = t;
            for (int k = 0; k < 4; ++k) q.m[k] = int64_t(std::llround(ls[k] / double(1 << t))) * (int64_t(1) << t);
            canonical_matrix(q);
            const double b = cost(q);
            if (b < cand_bits) { cand_bits = b; cand = q; }
        }
        if (pts.size() <= kRefineMaxVertices) {
            for (int pass = 0; pass < 8; ++pass) {
                bool better = false;
                for (int k = 0; k < 4; ++k)
                    for (int sgn : {-1, 1}) {
                        PolygonPlan q = cand;
                        q.m[k] += sgn * (int64_t(1) << q.matrix_shift);
                        if (q.m[k] < -kConicMaxMatrix || q.m[k] > kConicMaxMatrix) continue;
                        canonical_matrix(q);
                        const double b = cost(q);
                        if (b < cand_bits) { cand_bits = b; cand = q; better = true; }
                    }
                if (!better) break;
            }
        }
        if (cand_bits < best_bits) { best_bits = cand_bits; best = cand; }
    }
};

}  // namespace

void conic_rotation_for(size_t n, int64_t cs[2]) {
    const double a = 2.0 * 3.14159265358979323846 / double(n);
    cs[0] = std::llround(std::cos(a) * double(kConicOne));
    cs[1] = std::llround(std::sin(a) * double(kConicOne));
}

PolygonPlan plan_polygon(const PolygonModels& pm, const std::vector<PolygonVertex>& pts) {
    std::vector<PolygonVertex> copy = pts;
    Planner pl{pm, copy};
    PolygonPlan best;
    best.shift = pl.lattice_shift();
    best.mode = 0;
    double best_bits = pl.cost(best);
    PolygonPlan second = best;
    second.mode = 1;
    if (const double b = pl.cost(second); b < best_bits) { best_bits = b; best = second; }
    if (pts.size() >= 3) pl.try_conic(best, best_bits);
    return best;
}

}  // namespace spt::detail
