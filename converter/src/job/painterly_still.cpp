#include "job/painterly_still.hpp"

#include "io/trial_output.hpp"
#include "job/still_setup.hpp"
#include "paint/rate_control.hpp"
#include "spt/render.hpp"
#include "spt/writer.hpp"

namespace spt::job {

size_t still_set_count(const PaintJob& o, uint32_t width, uint32_t height) {
    return o.set_sizes.empty() ? paint::default_sets(width, height, o.sets).size() : o.set_sizes.size();
}

Result<PainterlyStill> paint_painterly_still(const PaintJob& o, const io::Image& img, const StillTarget& to) {
    const uint32_t W = img.width, H = img.height;
    auto still = still_setup(o, W, H);
    if (!still) return still.error();
    paint::PaintSetup setup = std::move(still->setup);
    paint::PaintOptions po = std::move(still->paint);
    StreamInfo info;
    info.rois = std::move(still->rois);

    auto renderer = Renderer::create(setup.header, setup.templates);
    if (!renderer) return make_error(renderer.error().code, "cannot set up the renderer: " + renderer.error().message);

    info.header = setup.header;
    info.templates = setup.templates;
    info.metadata = to.metadata;
    WriterOptions wo;
    wo.coding = o.stored ? Coding::Stored : o.coding == 1 ? Coding::Range : Coding::Replay;
    wo.atomic_rename = to.atomic_rename;
    const paint::ImageView model{W, H, img.rgb.data()};
    if (o.target_bytes > 0) {
        // Rate control (paint/rate_control.hpp): full paints at searched lambdas, each coded to
        // a trial file that has no name (io/trial_output.hpp) to measure its exact size.
        auto trial_file = io::TrialOutput::create(to.path);
        if (!trial_file) return trial_file.error();
        WriterOptions two = wo;
        two.atomic_rename = false;  // the trial file is never linked anywhere
        auto trial = [&](double lambda) {
            paint::PaintOptions tp = po;
            tp.lambda = lambda;
            tp.target_psnr = 0;
            Canvas c(W, H, o.background);
            std::vector<Stroke> out;
            const paint::PaintStats ts = paint::paint(model, c, **renderer, setup, tp, out);
            paint::RatePoint p{lambda, ~uint64_t(0), ts.psnr};
            auto w = Writer::create(trial_file->path(), info, two);
            if (!w) return p;
            Frame f;
            f.added = std::move(out);
            f.replay = paint::replay_info(setup, tp, W, H);
            if ((*w)->append(f) && (*w)->finish()) p.bytes = (*w)->stats().total_bytes;
            return p;
        };
        po.lambda = search_target_bytes(o, trial, po.lambda);
    }

    PainterlyStill r;
    r.canvas = Canvas(W, H, o.background);
    std::vector<Stroke> strokes;
    r.stats = paint::paint(model, r.canvas, **renderer, setup, po, strokes, nullptr, to.progress);

    auto writer = Writer::create(to.path, info, wo);
    if (!writer) return writer.error();
    Frame frame;
    frame.index = 0;
    frame.type = FrameType::Key;
    frame.added = std::move(strokes);
    frame.replay = paint::replay_info(setup, po, W, H);  // coding 2 replays the painter's candidates
    Status s = (*writer)->append(frame);
    if (s) s = (*writer)->finish();
    if (!s) {
        (*writer)->abort();
        return s.error();  // names the file
    }
    r.bytes = (*writer)->stats().total_bytes;
    return r;
}

}  // namespace spt::job
