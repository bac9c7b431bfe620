#include "video/video_encoder.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "paint/change_mask.hpp"
#include "paint/orientation.hpp"
#include "paint/rate_control.hpp"
#include "spt/reader.hpp"
#include "video/stroke_cull.hpp"

namespace spt::video {

namespace {

using Clock = std::chrono::steady_clock;


double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

cv::Mat wrap_rgb(uint32_t w, uint32_t h, const uint8_t* rgb) {
    return cv::Mat(int(h), int(w), CV_8UC3, const_cast<uint8_t*>(rgb));
}

}  // namespace

Result<std::unique_ptr<VideoEncoder>> VideoEncoder::create(const VideoPaintOptions& opts, uint32_t width,
                                                           uint32_t height, Rational fps,
                                                           std::vector<io::RoiRange> rois,
                                                           std::vector<std::pair<std::string, std::string>> metadata,
                                                           PaintFn painter) {
    if (width == 0 || height == 0) return make_error(Code::InvalidArgument, "video frames have no pixels");
    if (opts.block_size < 8 || opts.block_size > 256)
        return make_error(Code::InvalidArgument, "motion block size must be 8..256, got " + std::to_string(opts.block_size));
    if (opts.keyframe_interval < 1)
        return make_error(Code::InvalidArgument, "key frame interval must be at least 1");
    std::unique_ptr<VideoEncoder> e(new VideoEncoder());
    e->opts_ = opts;
    if (painter) {
        e->painter_ = std::move(painter);
    } else {
        e->painter_ = [](const paint::ImageView& m, Canvas& c, const Renderer& r, const paint::PaintSetup& s,
                         const paint::PaintOptions& o, std::vector<Stroke>& out, const std::vector<uint8_t>* region) {
            return paint::paint(m, c, r, s, o, out, region);
        };
    }
    CutOptions co;
    co.factor = opts.cut_threshold;
    co.window = opts.cut_window;
    e->cuts_ = CutDetector(co);
    e->flow_ = std::make_unique<FlowEstimator>(opts.flow, opts.flow_width);

    Header& h = e->setup_.header;
    h.width = width;
    h.height = height;
    h.fps = fps;
    h.background = opts.background;
    h.sets = paint::default_sets(width, height, opts.sets);
    h.orientations = default_orientations(8);
    e->setup_.templates = opts.templates.empty() ? paint::default_templates() : opts.templates;
    // Format 1.3 targets: the file's header says so; the painter paints an 8-bit proxy canvas
    // (with alpha when the file has it) of the same geometry.
    e->file_header_ = paint::scene_header(h, opts.scene);
    e->linear_ = opts.scene.linear;
    if (e->linear_) e->transform_ = paint::ProxyTransform::with_peak(opts.scene_peak);
    h.alpha = opts.scene.alpha;
    if (e->linear_) h.background = paint::proxy_background(opts.background, e->transform_);
    // The band renderer copies 8-bit colour rows only: alpha canvases render whole frames.
    e->opts_.incremental_render = opts.incremental_render && !h.alpha;

    Result<std::unique_ptr<Renderer>> r = Renderer::create(h, e->setup_.templates);
    if (!r) return r.error();
    e->renderer_ = std::move(*r);
    if (e->opts_.incremental_render) {
        Result<std::unique_ptr<BandRenderer>> b = BandRenderer::create(h, e->setup_.templates, *e->renderer_);
        if (!b) return b.error();
        e->band_ = std::move(*b);
    }

    if (e->linear_) {
        Result<std::unique_ptr<Renderer>> lr = Renderer::create(e->file_header_, e->setup_.templates);
        if (!lr) return lr.error();
        e->lin_renderer_ = std::move(*lr);
        e->lin_canvas_ = Canvas(e->file_header_);
    }

    StreamInfo info;
    info.header = e->file_header_;
    info.templates = e->setup_.templates;
    info.metadata = std::move(metadata);
    WriterOptions wo;
    wo.coding = opts.stored_coding ? Coding::Stored : opts.coding == 1 ? Coding::Range : Coding::Replay;
    wo.atomic_rename = opts.atomic_rename;
    Result<std::unique_ptr<Writer>> w = Writer::create(opts.output, info, wo);
    if (!w) return w.error();
    e->writer_ = std::move(*w);

    e->rois_ = std::move(rois);
    e->roi_used_.assign(e->rois_.size(), {-1, -1});
    e->canvas_ = Canvas(h);
    return e;
}

VideoEncoder::~VideoEncoder() {
    if (writer_ && !finished_) writer_->abort();
}

uint64_t VideoEncoder::bytes_written() const { return writer_ ? writer_->stats().total_bytes : 0; }

paint::PaintOptions VideoEncoder::frame_paint_options(long source_number, uint32_t index) const {
    paint::PaintOptions po = opts_.paint;
    po.seed = frame_seed(opts_.paint.seed, index);
    po.lambda = opts_.paint.lambda * lambda_scale_;
    po.rois.clear();
    for (const io::RoiRange& r : rois_) {
        if (source_number < r.first_frame || source_number > r.last_frame) continue;
        po.rois.push_back({r.x, r.y, r.w, r.h});
    }
    for (const auto& r : opts_.paint.rois) po.rois.push_back(r);
    return po;
}

// Mean absolute difference per channel between the canvas and the model, smoothed so that
// isolated pixels (a stroke's edge one pixel off) do not call for repainting.
void VideoEncoder::error_map(const paint::ImageView& model, cv::Mat& err) const {
    cv::Mat diff;
    cv::absdiff(wrap_rgb(canvas_.width, canvas_.height, canvas_.rgb.data()),
                wrap_rgb(model.width, model.height, model.rgb), diff);
    cv::Mat f;
    if (model.alpha && canvas_.alpha.size() == size_t(model.width) * model.height) {
        // Alpha canvases: the alpha channel counts like a fourth colour channel.
        diff.convertTo(f, CV_32FC3, 1.0 / 4.0);
        cv::transform(f, err, cv::Matx13f(1.f, 1.f, 1.f));
        cv::Mat da, fa;
        cv::absdiff(cv::Mat(int(model.height), int(model.width), CV_8U, const_cast<uint8_t*>(canvas_.alpha.data())),
                    cv::Mat(int(model.height), int(model.width), CV_8U, const_cast<uint8_t*>(model.alpha)), da);
        da.convertTo(fa, CV_32F, 1.0 / 4.0);
        err += fa;
    } else {
        diff.convertTo(f, CV_32FC3, 1.0 / 3.0);
        cv::transform(f, err, cv::Matx13f(1.f, 1.f, 1.f));
    }
    cv::blur(err, err, cv::Size(7, 7));
}

Status VideoEncoder::remove_transparent(const paint::ImageView& model, Frame& frame, std::vector<Stroke>& moved) {
    if (!model.alpha) return {};
    const uint32_t W = model.width, H = model.height;
    std::vector<uint32_t> extra;  // indices into moved
    Mask scratch;
    for (size_t k = 0; k < moved.size(); ++k) {
        const Stroke& s = moved[k];
        const Mask* m = &scratch;
        int64_t ox = 0, oy = 0;
        if (s.kind == StrokeKind::Stamp && s.stamp.color.a == 255) {
            m = &renderer_->stamp_footprint(s.stamp.set, s.stamp.tmpl, s.stamp.orient);
            ox = Renderer::stamp_pixel(s.stamp.x);
            oy = Renderer::stamp_pixel(s.stamp.y);
        } else if (Status st = renderer_->stroke_mask(s, scratch); !st) {
            return st;
        }
        ox += m->x0;
        oy += m->y0;
        // Coverage on the canvas, and the part of it over pixels the source has at most a
        // quarter opaque. A stroke entirely off the canvas has none and is left to the cull.
        uint64_t all = 0, clear = 0;
        const int64_t x0 = std::max<int64_t>(0, ox), y0 = std::max<int64_t>(0, oy);
        const int64_t x1 = std::min<int64_t>(W, ox + int64_t(m->w)), y1 = std::min<int64_t>(H, oy + int64_t(m->h));
        for (int64_t y = y0; y < y1; ++y) {
            const uint8_t* a = m->a.data() + size_t(y - oy) * m->w;
            const uint8_t* ma = model.alpha + size_t(y) * W;
            for (int64_t x = x0; x < x1; ++x) {
                all += a[x - ox];
                if (ma[x] < 64) clear += a[x - ox];
            }
        }
        if (all > 0 && double(clear) > opts_.transparent_share * double(all)) extra.push_back(uint32_t(k));
    }
    if (extra.empty()) return {};
    // moved[k] is the k-th stroke of live_ the frame does not already remove.
    std::vector<uint32_t> kept;
    kept.reserve(moved.size());
    size_t r = 0;
    for (uint32_t i = 0; i < live_.size(); ++i) {
        if (r < frame.removed.size() && frame.removed[r] == i) { ++r; continue; }
        kept.push_back(i);
    }
    std::vector<uint32_t> removed = frame.removed;
    for (uint32_t k : extra) removed.push_back(kept[k]);
    std::sort(removed.begin(), removed.end());
    frame.removed = std::move(removed);
    moved = live_;
    return apply_frame(moved, frame, setup_.header);
}

Status VideoEncoder::linear_frame(const paint::LinearView& linear, const Frame& frame, Frame& out) {
    out = frame;
    if (frame.type == FrameType::Key) {
        live_lin_.clear();
        lin_canvas_.reset(file_header_);
    } else {
        Frame edit = frame;
        edit.added.clear();
        if (Status st = apply_frame(live_lin_, edit, file_header_); !st) return st;
        if (Status st = lin_renderer_->render(lin_canvas_, live_lin_, unsigned(std::max(0, opts_.paint.threads))); !st)
            return st;
    }
    if (Status st = paint::refit_linear(linear, transform_, file_header_, *lin_renderer_, lin_canvas_, out.added,
                                        opts_.scene.refit);
        !st)
        return st;
    live_lin_.insert(live_lin_.end(), out.added.begin(), out.added.end());
    return {};
}

void VideoEncoder::update_orientation(const paint::ImageView& model, const cv::Mat& map, const cv::Mat& region) {
    if (opts_.paint.orient == paint::OrientMode::Random) {
        orient_.clear();
        paint_orient_.clear();
        return;
    }
    const int w = int(model.width), h = int(model.height);
    const size_t n = size_t(w) * size_t(h);
    if (map.empty() || orient_.size() != n || since_orient_ + 1 >= uint32_t(std::max(1, opts_.orient_refresh))) {
        orient_ = paint::orientation_field(model, setup_.header.orientations, opts_.paint.orient);
        since_orient_ = 0;
    } else {
        // The field travels with the content (nearest neighbour: indices do not interpolate).
        cv::Mat cur(h, w, CV_8U, orient_.data()), warped;
        cv::remap(cur, warped, map, cv::noArray(), cv::INTER_NEAREST, cv::BORDER_REPLICATE);
        std::copy(warped.data, warped.data + n, orient_.begin());
        ++since_orient_;
    }
    paint_orient_ = orient_;
    if (!opts_.flow_orientation || region.empty() || flow_field_.size() != region.size()) return;
    // Moving areas: strokes laid along the motion (what motion blur leaves of the detail).
    const float min2 = float(opts_.flow_orient_min * opts_.flow_orient_min);
    const auto& table = setup_.header.orientations;
    for (int y = 0; y < h; ++y) {
        const uint8_t* m = region.ptr<uint8_t>(y);
        const cv::Vec2f* f = flow_field_.ptr<cv::Vec2f>(y);
        uint8_t* o = paint_orient_.data() + size_t(y) * size_t(w);
        for (int x = 0; x < w; ++x) {
            if (!m[x] || f[x][0] * f[x][0] + f[x][1] * f[x][1] < min2) continue;
            o[x] = paint::nearest_orientation(table, std::atan2(double(f[x][1]), double(f[x][0])));
        }
    }
}

// Of `candidates` (indices into live_, increasing), those whose footprint meets `changed`.
Result<std::vector<uint32_t>> VideoEncoder::strokes_touching(const std::vector<uint32_t>& candidates,
                                                             const paint::ChangeMask& changed) const {
    std::vector<uint32_t> out;
    const uint32_t W = setup_.header.width, H = setup_.header.height;
    Mask scratch;
    for (uint32_t i : candidates) {
        if (i >= live_.size()) continue;
        const Stroke& s = live_[i];
        const Mask* m = &scratch;
        int64_t ox = 0, oy = 0;
        if (s.kind == StrokeKind::Stamp) {
            m = &renderer_->stamp_footprint(s.stamp.set, s.stamp.tmpl, s.stamp.orient);
            ox = Renderer::stamp_pixel(s.stamp.x);
            oy = Renderer::stamp_pixel(s.stamp.y);
        } else if (Status st = renderer_->stroke_mask(s, scratch); !st) {
            return st.error();
        }
        ox += m->x0;
        oy += m->y0;
        // Entirely off the canvas: nothing shows it, and it goes now.
        const bool off = ox >= int64_t(W) || oy >= int64_t(H) || ox + int64_t(m->w) <= 0 || oy + int64_t(m->h) <= 0;
        if (off || paint::any_in(changed, W, H, ox, oy, ox + int64_t(m->w), oy + int64_t(m->h))) out.push_back(i);
    }
    return out;
}

// The changed pixels (before widening) whose painted colour (and alpha) is off by more than
// twice the RMS error `rms` in each channel, as a CV_8U 0/255 mask.
cv::Mat VideoEncoder::visibly_wrong(const paint::ImageView& model, const paint::ChangeMask& changed, double rms) const {
    const uint32_t W = model.width, H = model.height;
    cv::Mat wrong(int(H), int(W), CV_8U, cv::Scalar(0));
    const bool alpha = model.alpha && canvas_.alpha.size() == size_t(W) * H;
    const double limit = (alpha ? 4 : 3) * 4 * rms * rms;
    for (size_t i = 0; i < size_t(W) * H; ++i) {
        if (!changed.raw[i]) continue;
        const uint8_t* a = model.rgb + 3 * i;
        const uint8_t* b = canvas_.rgb.data() + 3 * i;
        double e = 0;
        for (int k = 0; k < 3; ++k) e += double(a[k] - b[k]) * double(a[k] - b[k]);
        if (alpha) e += double(model.alpha[i] - canvas_.alpha[i]) * double(model.alpha[i] - canvas_.alpha[i]);
        if (e > limit) wrong.data[i] = 255;
    }
    return wrong;
}

// Where this frame may repaint: the changed pixels of the source, and those of the painting
// (what the frame's motion and removals changed: `before` is the canvas they started from), as
// a CV_8U 0/255 mask.
cv::Mat VideoEncoder::touched_area(const paint::ChangeMask& changed, const Canvas& before) const {
    const uint32_t W = canvas_.width, H = canvas_.height;
    cv::Mat area(int(H), int(W), CV_8U);
    const bool alpha = canvas_.alpha.size() == size_t(W) * H && before.alpha.size() == canvas_.alpha.size();
    for (size_t i = 0; i < size_t(W) * H; ++i) {
        const uint8_t* a = canvas_.rgb.data() + 3 * i;
        const uint8_t* b = before.rgb.data() + 3 * i;
        const bool painted = a[0] != b[0] || a[1] != b[1] || a[2] != b[2] || (alpha && canvas_.alpha[i] != before.alpha[i]);
        area.data[i] = changed.mask[i] || painted ? 255 : 0;
    }
    return area;
}

Status VideoEncoder::encode_key(const paint::ImageView& model, Frame& frame, FrameResult& r) {
    frame.type = FrameType::Key;
    frame.removed.clear();
    frame.motion = MotionField{};
    frame.added.clear();
    canvas_.reset(setup_.header);
    paint::PaintOptions po = frame_paint_options(r.source_number, r.index);
    auto t0 = Clock::now();
    update_orientation(model, cv::Mat(), cv::Mat());
    if (!paint_orient_.empty()) po.orientation_field = &paint_orient_;
    r.seconds_orient = seconds_since(t0);
    t0 = Clock::now();
    painter_(model, canvas_, *renderer_, setup_, po, frame.added, nullptr);
    frame.replay = paint::replay_info(setup_, po, model.width, model.height);  // frame coding 2
    r.seconds_paint = seconds_since(t0);
    error_map(model, ref_err_);
    r.type = FrameType::Key;
    r.removed = uint32_t(live_.size());
    return {};
}

Status VideoEncoder::encode_inter(const paint::ImageView& model, const cv::Mat& gray, Frame& frame,
                                  FrameResult& r, bool& want_key, bool& unchanged) {
    frame.type = FrameType::Inter;
    // The frame touches only what changed since the previous frame: pixels whose source moved
    // by more than the target's RMS error (without a target, the painting's own). Nothing
    // changed: the frame codes nothing.
    const uint32_t W = model.width, H = model.height;
    const double rms = paint::rms_of_psnr(opts_.paint.target_psnr > 0 ? opts_.paint.target_psnr : last_psnr_);
    const paint::ChangeMask changed = paint::changed_pixels(model.rgb, prev_rgb_.data(), W, H, rms, paint::kChangeGrow,
                                                            model.alpha, model.alpha ? prev_alpha_.data() : nullptr);
    if (changed.empty()) {
        frame.removed.clear();
        frame.motion = MotionField{};
        frame.added.clear();
        flow_field_ = cv::Mat::zeros(gray.size(), CV_32FC2);
        r.type = FrameType::Inter;
        r.removed = 0;
        unchanged = true;
        return {};
    }
    // Hidden strokes are removed where the frame changes; elsewhere they stay hidden, unmoved.
    Result<std::vector<uint32_t>> hidden = strokes_touching(pending_removals_, changed);
    if (!hidden) return hidden.error();
    frame.removed = std::move(*hidden);
    auto t0 = Clock::now();
    flow_->compute(prev_gray_, gray, flow_field_);
    frame.motion = block_motion(flow_field_, opts_.block_size);
    if (is_still(frame.motion)) frame.motion = MotionField{};
    frame.added.clear();
    r.seconds_flow = seconds_since(t0);
    t0 = Clock::now();

    // The moved list, exactly as the decoder will have it before the new strokes.
    std::vector<Stroke> moved = live_;
    Status st = apply_frame(moved, frame, setup_.header);
    if (!st) return st;
    st = remove_transparent(model, frame, moved);
    if (!st) return st;
    const unsigned threads = unsigned(std::max(0, opts_.paint.threads));
    const Canvas before = canvas_;
    if (band_) {
        // Only the bands where strokes moved (the canvas holds the rendering of live_).
        Result<double> rows = band_->update(canvas_, live_, frame, moved, threads);
        if (!rows) return rows.error();
        r.rendered_fraction = *rows;
    } else {
        st = renderer_->render(canvas_, moved, threads);
        if (!st) return st;
        r.rendered_fraction = 1.0;
    }
    r.seconds_render = seconds_since(t0);

    // Repaint where the painting's error grew past the threshold: content that moved in ways
    // the block field does not carry, disocclusions, new content. Where the error merely stayed
    // what it was when the painter last worked there (texture it never matched) the old strokes
    // stay, so they do not flicker. That reference error travels with the motion; comparing
    // with the previous frame's error instead would let slow drift go unnoticed forever.
    cv::Mat err, baseline, region;
    error_map(model, err);
    cv::Mat map(flow_field_.size(), CV_32FC2);
    for (int y = 0; y < map.rows; ++y) {
        const cv::Vec2f* f = flow_field_.ptr<cv::Vec2f>(y);
        cv::Vec2f* m = map.ptr<cv::Vec2f>(y);
        for (int x = 0; x < map.cols; ++x) m[x] = cv::Vec2f(float(x) - f[x][0], float(y) - f[x][1]);
    }
    cv::remap(ref_err_, ref_err_, map, cv::noArray(), cv::INTER_LINEAR, cv::BORDER_REPLICATE);
    cv::dilate(ref_err_, baseline, cv::Mat::ones(5, 5, CV_8U));
    const double t = opts_.repaint_error;
    cv::Mat grown = (err > t) & (err > baseline + t * 0.5);
    // Only where the frame changed: the source, or the painting (strokes moved or removed).
    grown &= touched_area(changed, before);
    // And every changed pixel the painting shows visibly wrong, however small the thing that
    // changed (the 7 x 7 mean above dilutes a small lamp until it goes out).
    grown |= visibly_wrong(model, changed, rms);
    cv::dilate(grown, region, cv::Mat::ones(5, 5, CV_8U));
    r.repaint_fraction = double(cv::countNonZero(region)) / double(region.total());
    if (r.repaint_fraction > opts_.repaint_key_fraction) {
        want_key = true;
        return {};
    }
    t0 = Clock::now();
    update_orientation(model, map, region);
    r.seconds_orient = seconds_since(t0);
    if (r.repaint_fraction > 0) {
        t0 = Clock::now();
        std::vector<uint8_t> mask(region.data, region.data + region.total());
        paint::PaintOptions po = frame_paint_options(r.source_number, r.index);
        if (!paint_orient_.empty()) po.orientation_field = &paint_orient_;
        po.max_strokes = std::min<uint64_t>(po.max_strokes, opts_.max_inter_strokes);
        if (opts_.inter_threshold > 0) po.threshold = opts_.inter_threshold;
        painter_(model, canvas_, *renderer_, setup_, po, frame.added, &mask);
        frame.replay = paint::replay_info(setup_, po, model.width, model.height, &mask);
        r.seconds_paint = seconds_since(t0);
        // The painter's new result becomes the reference where it worked.
        cv::Mat after;
        error_map(model, after);
        after.copyTo(ref_err_, region);
    }
    live_ = std::move(moved);
    r.type = FrameType::Inter;
    r.removed = uint32_t(frame.removed.size());
    return {};
}

Result<FrameResult> VideoEncoder::add_frame(const uint8_t* rgb, const uint8_t* alpha, const paint::LinearView* linear,
                                            long source_number) {
    if (finished_) return make_error(Code::BadState, "video encoder already finished");
    if ((setup_.header.alpha && !alpha) || (linear_ && (!linear || !linear->rgba)))
        return make_error(Code::InvalidArgument, "video encoder: the frame lacks the alpha or linear planes its target needs");
    const auto t0 = Clock::now();
    const uint32_t w = setup_.header.width, h = setup_.header.height;
    paint::ImageView model{w, h, rgb, setup_.header.alpha ? alpha : nullptr};
    FrameResult r;
    r.index = next_index_;
    r.source_number = source_number;

    cv::Mat gray;
    cv::cvtColor(wrap_rgb(w, h, rgb), gray, cv::COLOR_RGB2GRAY);
    r.cut_score = cuts_.push(gray);
    r.cut = r.cut_score.cut && opts_.detect_cuts;

    Frame frame;
    frame.index = next_index_;
    bool unchanged = false;  // an inter frame where nothing changed: coded empty
    bool key = next_index_ == 0 || r.cut || since_key_ + 1 >= uint32_t(opts_.keyframe_interval);
    if (!key) {
        bool want_key = false;
        Status st = encode_inter(model, gray, frame, r, want_key, unchanged);
        if (!st) return st.error();
        key = want_key;
    }
    if (key) {
        Status st = encode_key(model, frame, r);
        if (!st) return st.error();
        live_.clear();
    }
    Status st;
    if (linear_) {
        Frame lin;
        st = linear_frame(*linear, frame, lin);
        if (st) st = writer_->append(lin);
    } else {
        st = writer_->append(frame);
    }
    if (!st) return st.error();
    r.added = uint32_t(frame.added.size());
    if (opts_.frame_byte_budget > 0) {
        // Rate control: the next frame's lambda follows the running ratio of bytes spent to
        // bytes allowed so far (bytes fall roughly as lambda^-1/2 near the default, hence the
        // cube: a 10% overshoot raises lambda by a third). Clamped to 1/16..256.
        const double spent = double(writer_->stats().frame_bytes);
        const double allowed = opts_.frame_byte_budget * double(next_index_ + 1);
        lambda_scale_ = std::clamp(std::pow(spent / allowed, 3.0), 1.0 / 16, 256.0);
    }
    live_.insert(live_.end(), frame.added.begin(), frame.added.end());

    // Book-keeping for the next frame.
    since_key_ = key ? 0 : since_key_ + 1;
    prev_gray_ = gray;
    prev_rgb_.assign(rgb, rgb + size_t(w) * h * 3);
    if (model.alpha) prev_alpha_.assign(model.alpha, model.alpha + size_t(w) * h);
    if (!unchanged) pending_removals_.clear();
    if (!unchanged && opts_.cull_every > 0 && (next_index_ % uint32_t(opts_.cull_every)) == 0) {
        const auto tc = Clock::now();
        Result<std::vector<uint32_t>> hidden = hidden_strokes(live_, *renderer_, w, h, scratch_);
        if (!hidden) return hidden.error();
        pending_removals_ = std::move(*hidden);
        r.seconds_cull = seconds_since(tc);
    }
    for (size_t i = 0; i < rois_.size(); ++i) {
        if (source_number < rois_[i].first_frame || source_number > rois_[i].last_frame) continue;
        if (roi_used_[i].first < 0) roi_used_[i].first = next_index_;
        roi_used_[i].second = next_index_;
    }

    r.live = uint32_t(live_.size());
    r.psnr = paint::psnr(model, canvas_.rgb.data());
    last_psnr_ = r.psnr;
    r.seconds = seconds_since(t0);
    ++next_index_;
    report_.frames++;
    if (key) {
        report_.key_frames++;
        report_.key_frame_indices.push_back(r.index);
        report_.seconds_key += r.seconds;
    } else {
        report_.seconds_inter += r.seconds;
    }
    if (r.cut) report_.cuts++;
    report_.strokes_added += r.added;
    report_.strokes_removed += r.removed;
    report_.max_live = std::max<uint64_t>(report_.max_live, live_.size());
    psnr_sum_ += r.psnr;
    if (r.psnr < report_.min_psnr) {
        report_.min_psnr = r.psnr;
        report_.min_psnr_frame = r.index;
    }
    if (!paint::reaches_target(r.psnr, opts_.paint.target_psnr)) report_.frames_short++;
    report_.mean_psnr = psnr_sum_ / double(report_.frames);
    report_.bytes = writer_->stats().total_bytes;
    return r;
}

Status VideoEncoder::finish() {
    if (finished_) return make_error(Code::BadState, "video encoder already finished");
    for (size_t i = 0; i < rois_.size(); ++i) {
        if (roi_used_[i].first < 0) continue;
        const io::RoiRange& s = rois_[i];
        Roi roi{uint32_t(roi_used_[i].first), uint32_t(roi_used_[i].second), uint32_t(s.x), uint32_t(s.y),
                uint32_t(s.w), uint32_t(s.h)};
        Status st = writer_->add_roi(roi);
        if (!st) return st;
    }
    Status st = writer_->finish();
    finished_ = true;
    report_.bytes = writer_->stats().total_bytes;
    return st;
}

void VideoEncoder::abort() {
    if (writer_ && !finished_) writer_->abort();
    finished_ = true;
}

}  // namespace spt::video
