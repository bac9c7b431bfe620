#include "cartoon/inter_frame.hpp"

#include <cmath>
#include <future>

#include "cartoon/cartoon_paint.hpp"
#include "cartoon/frame_diff.hpp"
#include "cartoon/shape_cost.hpp"
#include "cartoon/stamp_keep.hpp"
#include "paint/change_mask.hpp"
#include "paint/worker_pool.hpp"
#include "spt/reader.hpp"

namespace spt::cartoon {

double frame_cost(const Frame& f) {
    double c = 0.3 * double(f.removed.size());
    for (const Stroke& s : f.added)
        c += shape_bytes(s, 5.6);
    return c;
}

namespace {

// Per pixel, 1 where `shown` is visibly wrong for `model`: its squared error (summed over the
// channels) above 12 times the target's mean squared error per channel, twice the target's
// RMS error in each channel. Codec noise at the target's level stays under it. (Insensitive:
// 4 and 48 times give 91,228 and 90,803 bytes on the butterfly, 12 91,611.)
std::vector<uint8_t> visibly_wrong(const paint::ImageView& model, const Canvas& shown, double target_psnr) {
    const double mse = 255.0 * 255.0 / std::pow(10.0, target_psnr / 10.0);
    const int64_t limit = int64_t(12 * mse);
    std::vector<uint8_t> wrong(size_t(model.width) * model.height);
    const uint8_t* a = model.rgb;
    const uint8_t* b = shown.rgb.data();
    for (size_t p = 0; p < wrong.size(); ++p, a += 3, b += 3) {
        const int dr = a[0] - b[0], dg = a[1] - b[1], db = a[2] - b[2];
        wrong[p] = int64_t(dr * dr + dg * dg + db * db) > limit;
    }
    return wrong;
}

// What the frame keeps, moves, removes and adds before its new stamps, strict (`lenient` false:
// an old polygon stays only when it traced the same) or lenient (frame_diff.hpp DiffOptions);
// `canvas` holds it as a decoder draws it.
Result<InterFrame> plan_variant(const InterInput& in, bool lenient) {
    const std::vector<Stroke>& live = *in.live;
    const Renderer& renderer = *in.renderer;
    const Header& header = in.setup->header;
    const int W = int(in.model.width), H = int(in.model.height);
    DiffOptions dopt;
    dopt.stand_ins = lenient;
    std::vector<uint8_t> wrong;
    if (lenient && in.shown && in.paint.target_psnr > 0) {
        wrong = visibly_wrong(in.model, *in.shown, in.paint.target_psnr);
        dopt.wrong = &wrong;
    }
    // Polygons by the frame diff; old stamps by what they still do for the new frame
    // (stamp_keep.hpp), not by whether the source under them flickered.
    auto diff = [&](const MotionChoice& mc) {
        FrameDiff fd = diff_frame(mc.moved, *in.polygons, renderer, W, H, dopt);
        fd.removed = drop_unhelpful_stamps(mc.moved, fd.removed, fd.added, in.model, renderer, header);
        return fd;
    };
    MotionChoice m = choose_motion(live, *in.polygons, in.cur, in.prev, renderer, header, in.motion);
    FrameDiff d = diff(m);
    if (!m.field.empty()) {
        // The field pays only when it keeps more than it costs: a vector moves every stroke of
        // its block, and what it moves wrongly is drawn again.
        MotionOptions still = in.motion;
        still.enabled = false;
        MotionChoice z = choose_motion(live, *in.polygons, in.cur, in.prev, renderer, header, still);
        FrameDiff dz = diff(z);
        if (kept_value(live, dz.removed) >= kept_value(live, d.removed) - motion_cost(m.field)) {
            m = std::move(z);
            d = std::move(dz);
        }
    }
    InterFrame r;
    r.lenient = lenient;
    r.stood_in = d.stood_in;
    r.left_out = d.left_out;
    r.polygons_added = d.added.size();
    r.polygons_kept = in.polygons->size() - d.added.size() - d.left_out;
    Frame& f = r.frame;
    f.type = FrameType::Inter;
    f.motion = std::move(m.field);
    f.removed = std::move(d.removed);
    f.added = std::move(d.added);
    // The canvas before the residual stamps: what a decoder shows with this frame's polygons.
    std::vector<Stroke> next = live;
    if (Status s = apply_frame(next, f, header); !s) return s.error();
    r.canvas = Canvas(header);
    if (Status s = renderer.render(r.canvas, next); !s) return s.error();
    r.kept_psnr = paint::psnr(in.model, r.canvas.rgb.data());
    return r;
}

// The new stamps, painted on the plan's canvas to the target; only inside `within` when given.
void paint_stamps(const InterInput& in, InterFrame& r, const std::vector<uint8_t>* within = nullptr) {
    Frame& f = r.frame;
    // A stamp must pay for itself 16 times more (kResidualLambdaScale). (12 frames at 36 dB,
    // inter frames' lambda times 1 / 2 / 4 / 8 / 16 / 32 / 64: butterfly 91,611 / 85,228 / 80,717 /
    // 79,534 / 78,028 / 77,597 / 77,398 bytes, taffy 525,668 / 463,324 / 422,076 / 403,274 /
    // 399,014 / 395,991 / 396,856, star 4,122 / 4,103 / 4,055 / 4,012 / 3,982 / 3,959 / 3,911;
    // 32 and 64 paint taffy 40% slower, and 128 leaves taffy frames under the target.)
    paint::PaintOptions po = in.paint;
    if (po.target_psnr > 0) po.lambda *= kResidualLambdaScale;
    if (!(po.target_psnr > 0 && r.kept_psnr >= po.target_psnr)) {
        // (Painting first only where the kept canvas is really worse than the target needs,
        // 7 x 7 mean squared error over 4 times the target's, then wherever the error is, gave
        // butterfly 61,559 bytes instead of 61,979, taffy 384,468 instead of 383,993, star 3,982
        // instead of 3,965: not worth a second region.)
        std::vector<uint8_t> region = residual_region(in.model, r.canvas, 24, 2);
        if (within && !region.empty()) {
            bool any = false;
            for (size_t i = 0; i < region.size(); ++i) any |= (region[i] &= (*within)[i]) != 0;
            if (!any) region.clear();
        }
        if (!region.empty()) {
            std::vector<Stroke> stamps;
            paint::paint(in.model, r.canvas, *in.renderer, *in.setup, po, stamps, &region);
            r.stamps = stamps.size();
            // The stamps replay after the added polygons (SPEC.md 7.7.5).
            if (!stamps.empty()) f.replay = paint::replay_info(*in.setup, po, in.model.width, in.model.height, &region);
            f.added.insert(f.added.end(), stamps.begin(), stamps.end());
        }
    }
    r.cost = frame_cost(f);
}

// The patch: every stroke of the previous frame stays where it is, and stamps are painted only
// where the source changed (`changed`), so that the frame costs what changed.
InterFrame plan_patch(const InterInput& in, const std::vector<uint8_t>& changed) {
    InterFrame r;
    r.frame.type = FrameType::Inter;
    r.patched = true;
    r.canvas = *in.shown;
    r.kept_psnr = paint::psnr(in.model, r.canvas.rgb.data());
    for (const Stroke& s : *in.live) r.polygons_kept += s.kind != StrokeKind::Stamp;
    paint_stamps(in, r, &changed);
    return r;
}

bool same_plan(const Frame& a, const Frame& b) {
    return a.removed == b.removed && a.added == b.added && a.motion.vectors == b.motion.vectors;
}

}  // namespace

bool better_at_target(const InterFrame& a, const InterFrame& b, const paint::ImageView& model, double target_psnr) {
    const double pa = paint::psnr(model, a.canvas.rgb.data());
    const double pb = paint::psnr(model, b.canvas.rgb.data());
    const bool reach_a = pa >= target_psnr, reach_b = pb >= target_psnr;
    if (reach_a != reach_b) return reach_b;
    if (!reach_a) return pb > pa;
    return b.cost < a.cost;
}

Result<InterFrame> paint_inter_frame(const InterInput& in) {
    // What changed since the previous frame, by more than the target's RMS error (without a
    // target, the previous painting's own): nothing, and the frame codes nothing.
    const double psnr_before = paint::psnr(in.model, in.shown->rgb.data());
    const double rms = paint::rms_of_psnr(in.paint.target_psnr > 0 ? in.paint.target_psnr : psnr_before);
    const paint::ChangeMask changed =
        paint::changed_pixels(in.cur.data, in.prev.data, in.model.width, in.model.height, rms, paint::kChangeGrow);
    if (changed.empty()) {
        InterFrame r;
        r.frame.type = FrameType::Inter;
        r.canvas = *in.shown;
        r.kept_psnr = psnr_before;
        r.unchanged = true;
        for (const Stroke& s : *in.live) r.polygons_kept += s.kind != StrokeKind::Stamp;
        return r;
    }
    // Otherwise three plans: the patch (every stroke kept, stamps where the source changed),
    // and the retraced frame, strict and lenient; the cheapest at the target is written
    // (better_at_target), so a frame never costs more than patching what changed.
    InterFrame patch = plan_patch(in, changed.mask);
    auto retraced = paint_retraced(in);
    if (!retraced) return retraced.error();
    const double target = in.paint.target_psnr;
    bool take_patch = !better_at_target(patch, *retraced, in.model, target);
    if (!(target > 0))
        take_patch = patch.cost <= retraced->cost ||
                     paint::psnr(in.model, patch.canvas.rgb.data()) > paint::psnr(in.model, retraced->canvas.rgb.data());
    return take_patch ? std::move(patch) : std::move(*retraced);
}

Result<InterFrame> paint_retraced(const InterInput& in) {
    // The two plans are independent (each reads the inputs, the renderer's caches are thread
    // safe): with more than one thread the lenient one is made beside the strict one.
    const bool parallel = paint::resolve_threads(in.paint.threads) > 1;
    auto later = [&](auto fn) { return std::async(parallel ? std::launch::async : std::launch::deferred, fn); };
    auto lenient_plan = later([&] { return plan_variant(in, true); });
    auto strict = plan_variant(in, false);
    auto lenient = lenient_plan.get();
    if (!strict) return strict.error();
    if (!lenient) return lenient.error();
    // Leniency changed nothing (no old polygon stood in, none was left out): one painting.
    if (same_plan(strict->frame, lenient->frame)) {
        paint_stamps(in, *strict);
        return std::move(*strict);
    }
    auto lenient_stamps = later([&] { paint_stamps(in, *lenient); });
    paint_stamps(in, *strict);
    lenient_stamps.get();
    // Both reach the target: the cheaper. One does: that one. Neither: the closer to it.
    // Without a target, fewer bytes must not cost quality: the lenient one only when it is
    // both cheaper and no worse.
    const double target = in.paint.target_psnr;
    bool take_lenient = better_at_target(*strict, *lenient, in.model, target);
    if (!(target > 0))
        take_lenient = lenient->cost < strict->cost && paint::psnr(in.model, lenient->canvas.rgb.data()) >=
                                                           paint::psnr(in.model, strict->canvas.rgb.data());
    return take_lenient ? std::move(*lenient) : std::move(*strict);
}

}  // namespace spt::cartoon
