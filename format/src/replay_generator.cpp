// The candidate generator of frame coding 2 (SPEC.md 7.7.1, 7.7.2): candidate regions as bands
// of rows sharing one list of allowed intervals, so the k-th allowed pixel is found by two
// binary searches whatever the canvas size.
#include <algorithm>
#include <string>

#include "spt/replay.hpp"

namespace spt::replay {
namespace {

constexpr size_t kMaxRects = 4096;

// Intersection of two sorted lists of disjoint intervals.
void intersect(const std::vector<uint32_t>& a0, const std::vector<uint32_t>& a1, const std::vector<uint32_t>& b0,
               const std::vector<uint32_t>& b1, std::vector<uint32_t>& o0, std::vector<uint32_t>& o1) {
    o0.clear();
    o1.clear();
    size_t i = 0, j = 0;
    while (i < a0.size() && j < b0.size()) {
        const uint32_t lo = std::max(a0[i], b0[j]), hi = std::min(a1[i], b1[j]);
        if (lo < hi) { o0.push_back(lo); o1.push_back(hi); }
        if (a1[i] < b1[j]) ++i; else ++j;
    }
}

}  // namespace

std::string check_region(const ReplayRegion& r, uint32_t width, uint32_t height) {
    if (r.use_rects) {
        if (r.rects.empty() || r.rects.size() > kMaxRects)
            return std::to_string(r.rects.size()) + " rectangles, expected 1.." + std::to_string(kMaxRects);
        for (size_t i = 0; i < r.rects.size(); ++i) {
            const auto& q = r.rects[i];
            if (q.w == 0 || q.h == 0 || q.x >= width || q.y >= height || q.w > width - q.x || q.h > height - q.y)
                return "rectangle " + std::to_string(i) + " is empty or leaves the canvas";
        }
    }
    if (r.use_blocks) {
        if (r.block_size < 8 || r.block_size > 256) return "block size " + std::to_string(r.block_size) + " is not 8..256";
        const uint64_t cols = (uint64_t(width) + r.block_size - 1) / r.block_size;
        const uint64_t rows = (uint64_t(height) + r.block_size - 1) / r.block_size;
        if (r.blocks.size() != cols * rows) return "block mask is not ceil(W/B) x ceil(H/B)";
        for (uint8_t b : r.blocks)
            if (b > 1) return "block mask value other than 0 or 1";
    }
    return {};
}

struct CandidateDomain::Band {
    uint32_t y0 = 0, y1 = 0;             // rows [y0, y1)
    uint64_t start = 0;                  // allowed pixels before the band
    uint64_t per_row = 0;                // allowed pixels in each of its rows
    std::vector<uint32_t> x0, x1;        // sorted disjoint intervals [x0, x1)
    std::vector<uint64_t> before;        // allowed pixels of a row before interval i
};

CandidateDomain::CandidateDomain() = default;
CandidateDomain::~CandidateDomain() = default;
CandidateDomain::CandidateDomain(const CandidateDomain&) = default;
CandidateDomain::CandidateDomain(CandidateDomain&&) noexcept = default;
CandidateDomain& CandidateDomain::operator=(const CandidateDomain&) = default;
CandidateDomain& CandidateDomain::operator=(CandidateDomain&&) noexcept = default;

CandidateDomain::CandidateDomain(uint32_t width, uint32_t height, const ReplayRegion& region)
    : width_(width), height_(height) {
    all_ = !region.use_rects && !region.use_blocks;
    if (all_) {
        total_ = uint64_t(width) * height;
        return;
    }
    // Band boundaries: every rectangle edge and every block row edge.
    std::vector<uint32_t> ys{0, height};
    if (region.use_rects)
        for (const auto& q : region.rects) { ys.push_back(q.y); ys.push_back(q.y + q.h); }
    const uint32_t B = region.block_size;
    const uint32_t cols = region.use_blocks ? (width + B - 1) / B : 0;
    if (region.use_blocks)
        for (uint64_t y = B; y < height; y += B) ys.push_back(uint32_t(y));
    std::sort(ys.begin(), ys.end());
    ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
    std::vector<uint32_t> r0, r1, b0, b1, t0, t1;
    for (size_t k = 0; k + 1 < ys.size(); ++k) {
        const uint32_t y0 = ys[k], y1 = ys[k + 1];
        // Allowed columns of the band's rows: first the canvas, then each restriction.
        std::vector<uint32_t> c0{0}, c1{width};
        if (region.use_rects) {
            std::vector<std::pair<uint32_t, uint32_t>> iv;
            for (const auto& q : region.rects)
                if (q.y <= y0 && y1 <= q.y + q.h) iv.push_back({q.x, q.x + q.w});
            std::sort(iv.begin(), iv.end());
            r0.clear(); r1.clear();
            for (const auto& [a, b] : iv) {
                if (!r1.empty() && a <= r1.back()) r1.back() = std::max(r1.back(), b);
                else { r0.push_back(a); r1.push_back(b); }
            }
            intersect(c0, c1, r0, r1, t0, t1);
            c0.swap(t0); c1.swap(t1);
        }
        if (region.use_blocks) {
            const uint8_t* row = region.blocks.data() + size_t(y0 / B) * cols;
            b0.clear(); b1.clear();
            for (uint32_t c = 0; c < cols; ++c) {
                if (!row[c]) continue;
                const uint32_t a = c * B, b = std::min<uint64_t>(uint64_t(c + 1) * B, width);
                if (!b1.empty() && b1.back() == a) b1.back() = b;
                else { b0.push_back(a); b1.push_back(b); }
            }
            intersect(c0, c1, b0, b1, t0, t1);
            c0.swap(t0); c1.swap(t1);
        }
        if (c0.empty()) continue;
        Band band;
        band.y0 = y0;
        band.y1 = y1;
        band.start = total_;
        band.x0 = c0;
        band.x1 = c1;
        for (size_t i = 0; i < c0.size(); ++i) {
            band.before.push_back(band.per_row);
            band.per_row += c1[i] - c0[i];
        }
        total_ += band.per_row * (y1 - y0);
        bands_.push_back(std::move(band));
    }
}

void CandidateDomain::pixel(uint64_t k, uint32_t& x, uint32_t& y) const {
    if (all_) {
        x = uint32_t(k % width_);
        y = uint32_t(k / width_);
        return;
    }
    auto b = std::upper_bound(bands_.begin(), bands_.end(), k, [](uint64_t v, const Band& bd) { return v < bd.start; });
    const Band& band = *(b - 1);
    const uint64_t in = k - band.start;
    y = band.y0 + uint32_t(in / band.per_row);
    const uint64_t r = in % band.per_row;
    const size_t i = size_t(std::upper_bound(band.before.begin(), band.before.end(), r) - band.before.begin()) - 1;
    x = band.x0[i] + uint32_t(r - band.before[i]);
}

bool CandidateDomain::contains(uint32_t x, uint32_t y) const {
    if (x >= width_ || y >= height_) return false;
    if (all_) return true;
    for (const Band& b : bands_) {
        if (y < b.y0 || y >= b.y1) continue;
        for (size_t i = 0; i < b.x0.size(); ++i)
            if (x >= b.x0[i] && x < b.x1[i]) return true;
        return false;
    }
    return false;
}

Candidate candidate(uint64_t seed, uint32_t set, uint64_t counter, const CandidateDomain& domain, uint32_t templates,
                    uint32_t orientations) {
    Candidate c;
    domain.pixel(below(draw(seed, set, counter, Stream::Position), domain.size()), c.x, c.y);
    c.tmpl = uint8_t(below(draw(seed, set, counter, Stream::Template), templates));
    c.orient = uint8_t(below(draw(seed, set, counter, Stream::Orientation), orientations));
    return c;
}

}  // namespace spt::replay
