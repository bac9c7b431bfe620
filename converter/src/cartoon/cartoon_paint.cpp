#include "cartoon/cartoon_paint.hpp"

#include <cstdlib>

#include <opencv2/imgproc.hpp>

namespace spt::cartoon {

std::vector<uint8_t> residual_region(const paint::ImageView& model, const Canvas& canvas, int threshold, int grow) {
    cv::Mat m(int(model.height), int(model.width), CV_8U, cv::Scalar(0));
    bool any = false;
    for (uint32_t y = 0; y < model.height; ++y) {
        const uint8_t* a = model.rgb + size_t(y) * model.width * 3;
        const uint8_t* b = canvas.row(y);
        for (uint32_t x = 0; x < model.width; ++x) {
            const int e = std::abs(a[3 * x] - b[3 * x]) + std::abs(a[3 * x + 1] - b[3 * x + 1]) + std::abs(a[3 * x + 2] - b[3 * x + 2]);
            if (e > threshold) { m.at<uint8_t>(int(y), int(x)) = 1; any = true; }
        }
    }
    if (!any) return {};
    if (grow > 0) cv::dilate(m, m, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(2 * grow + 1, 2 * grow + 1)));
    return std::vector<uint8_t>(m.datastart, m.dataend);
}

FillLayer fill_for_target(const cv::Mat& rgb, Rgb8 background, const Renderer& renderer, const FillOptions& fo,
                          double target_psnr, const std::vector<cv::Vec3b>* palette, Canvas& canvas, double& psnr) {
    // With a target the fill layer alone can reach, the coarsest outline that reaches it
    // (fewest vertices); otherwise the given tolerance, and stamps for the rest.
    const paint::ImageView model{uint32_t(rgb.cols), uint32_t(rgb.rows), rgb.data};
    std::vector<double> tolerances;
    if (target_psnr > 0 && fo.search_tolerance) tolerances = {1.0, 0.7, 0.5};
    tolerances.push_back(fo.trace.epsilon);
    FillLayer fill;
    for (double eps : tolerances) {
        FillOptions f = fo;
        f.trace.epsilon = eps;
        fill = build_fill_layer(rgb, background, renderer, f, palette);
        fill.tolerance = eps;
        fill.smooth = f.trace.smooth;
        canvas.fill(background);
        for (const Stroke& s : fill.strokes) (void)renderer.draw(canvas, s);
        psnr = paint::psnr(model, canvas.rgb.data());
        if (target_psnr > 0 && psnr >= target_psnr) break;
    }
    return fill;
}

CartoonStats paint_cartoon(const paint::ImageView& model, Canvas& canvas, const Renderer& renderer,
                           const paint::PaintSetup& setup, const paint::PaintOptions& po, const FillOptions& fo,
                           std::vector<Stroke>& out) {
    CartoonStats st;
    const cv::Mat rgb(int(model.height), int(model.width), CV_8UC3, const_cast<uint8_t*>(model.rgb));
    double fill_psnr = 0;
    FillLayer fill = fill_for_target(rgb, setup.header.background, renderer, fo, po.target_psnr, nullptr, canvas, fill_psnr);
    st.colors = fill.colors;
    st.regions = fill.regions;
    st.grid = fill.grid;
    for (const Stroke& s : fill.strokes) {
        if (s.kind == StrokeKind::Curve) {
            ++st.lines;
            st.line_points += s.curve.points.size();
        } else {
            ++st.polygons;
            st.vertices += s.polygon.points.size();
        }
    }
    st.fill_psnr = fill_psnr;
    out.insert(out.end(), std::make_move_iterator(fill.strokes.begin()), std::make_move_iterator(fill.strokes.end()));
    st.stamps.psnr = st.fill_psnr;
    if (po.target_psnr > 0 && st.fill_psnr >= po.target_psnr) {
        st.stamps.stop = paint::StopReason::TargetPsnr;
        return st;
    }
    const std::vector<uint8_t> region = residual_region(model, canvas, 12, 2);
    if (region.empty()) return st;
    // As a sequence's (kResidualLambdaScale). Stills at 36 dB, lambda times 1 / 4 / 16 / 32 /
    // 128: taffy frame 30 37,497 / 32,060 / 30,937 / 30,663 / 24,135 bytes (the last at 35.54
    // dB, short of the target), butterfly frame 40 36,521 / 30,425 / 26,591 / 25,931 / 25,696.
    paint::PaintOptions scaled = po;
    if (scaled.target_psnr > 0) scaled.lambda *= kResidualLambdaScale;
    std::vector<Stroke> stamps;
    st.stamps = paint::paint(model, canvas, renderer, setup, scaled, stamps, &region);
    if (!stamps.empty()) st.replay = paint::replay_info(setup, scaled, model.width, model.height, &region);
    out.insert(out.end(), stamps.begin(), stamps.end());
    return st;
}

}  // namespace spt::cartoon
