#include "paint/scene_paint.hpp"

#include <algorithm>

namespace spt::paint {

bool has_transparency(const LinearView& img) {
    const size_t n = size_t(img.width) * img.height;
    for (size_t i = 0; i < n; ++i)
        if (img.rgba[4 * i + 3] < 1.0f) return true;
    return false;
}

double partial_alpha_share(const LinearView& img) {
    const size_t n = size_t(img.width) * img.height;
    if (n == 0) return 0;
    size_t partial = 0;
    for (size_t i = 0; i < n; ++i) {
        const float a = img.rgba[4 * i + 3];
        partial += a >= 16.f / 255.f && a <= 239.f / 255.f;
    }
    return double(partial) / double(n);
}

Header scene_header(const Header& plain, const SceneTarget& target) {
    Header h = plain;
    h.alpha = target.alpha;
    h.color = target.linear ? ColorEncoding::LinearHalf : ColorEncoding::Srgb8;
    h.background_lo = Rgb8{0, 0, 0};
    if (target.linear) set_linear_background(h, plain.background);
    return h;
}

Result<ScenePainting> paint_scene(const LinearView& img, const PaintSetup& setup, const PaintOptions& opts,
                                  const SceneTarget& target, double peak, const PaintProgressFn& progress) {
    ScenePainting out;
    const uint32_t W = img.width, H = img.height;
    if (W != setup.header.width || H != setup.header.height || !img.rgba)
        return make_error(Code::InvalidArgument, "paint_scene: the image and the setup differ in size");
    out.header = scene_header(setup.header, target);
    // An sRGB8 file is painted on the image's own sRGB encoding (values above 1 clip); a
    // linear one on the log-extended proxy of its peak.
    if (!target.linear) out.transform.peak = 1.0;
    else if (peak > 0) out.transform = ProxyTransform::with_peak(peak);
    else out.transform = proxy_for(img);

    std::vector<uint8_t> rgb, alpha;
    make_proxy(img, out.transform, rgb, target.alpha ? &alpha : nullptr);
    PaintSetup proxy = setup;
    proxy.header = out.header;
    proxy.header.color = ColorEncoding::Srgb8;
    proxy.header.background_lo = Rgb8{0, 0, 0};
    if (target.linear) proxy.header.background = proxy_background(setup.header.background, out.transform);
    auto pr = Renderer::create(proxy.header, proxy.templates);
    if (!pr) return pr.error();
    Canvas pc(proxy.header);
    const ImageView model{W, H, rgb.data(), target.alpha ? alpha.data() : nullptr};
    out.stats = paint(model, pc, **pr, proxy, opts, out.strokes, nullptr, progress);
    if (!target.linear) {
        out.canvas = std::move(pc);
        return out;
    }
    auto lr = Renderer::create(out.header, setup.templates);
    if (!lr) return lr.error();
    out.canvas = Canvas(out.header);
    if (Status st = refit_linear(img, out.transform, out.header, **lr, out.canvas, out.strokes, target.refit, &out.refit); !st)
        return st.error();
    return out;
}

}  // namespace spt::paint
