// TMPL coding 1 (SPEC.md 7.6): bitmap samples as MED-predicted residuals, range coded with
// contexts chosen by the local gradient.
#include "container.hpp"
#include "range_coder.hpp"

namespace spt::detail {
namespace {

int med(int a, int b, int c) {
    if (c >= std::max(a, b)) return std::min(a, b);
    if (c <= std::min(a, b)) return std::max(a, b);
    return a + b - c;
}

template <class C>
bool code_samples(C& c, Template& t) {
    Res8Model ctx[8];
    const int w = t.width, h = t.height;
    auto at = [&](int x, int y) { return (x < 0 || y < 0) ? 0 : int(t.pixels[size_t(y) * w + x]); };
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const int a = at(x - 1, y), b = at(x, y - 1), d = at(x - 1, y - 1);
            const int pred = med(a, b, d);
            const int activity = std::abs(a - d) + std::abs(b - d);
            const int q = std::min(7, bit_length(uint64_t(activity)));
            uint8_t& s = t.pixels[size_t(y) * w + x];
            const int r = code_res8(c, ctx[q], wrap8(int(s) - pred));
            if (r > 127) return false;
            s = uint8_t((pred + r) & 255);
        }
    }
    return true;
}

}  // namespace

void encode_template_samples(const Template& t, std::vector<uint8_t>& out) {
    RangeEncoder enc(out);
    Template copy = t;
    code_samples(enc, copy);
    enc.finish();
}

Status decode_template_samples(const uint8_t* p, size_t n, uint64_t off, Template& t) {
    t.pixels.assign(size_t(t.width) * t.height, 0);
    RangeDecoder dec(p, n);
    if (!code_samples(dec, t))
        return make_error(Code::Corrupt, "TMPL: sample residual +128 in the range-coded samples at byte offset " + std::to_string(off), off);
    if (!dec.consumed_all())
        return make_error(Code::Corrupt, "TMPL: bytes follow the range-coded samples at byte offset " + std::to_string(off), off);
    return {};
}

}  // namespace spt::detail
