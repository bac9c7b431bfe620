#include "job/painterly_sequence.hpp"

#include "io/template_loader.hpp"

namespace spt::job {

Status painterly_video_options(const PaintJob& o, video::VideoPaintOptions& v) {
    if (!o.preview.empty() || !o.side_by_side.empty())
        return make_error(Code::InvalidArgument, "--preview and --side-by-side are for still images; render a sequence with "
                    "'spt render " + o.output + " -o frame.####.png'");
    if (!o.set_sizes.empty())
        return make_error(Code::InvalidArgument, "--set-sizes is not supported for sequences yet; use --sets N");
    v.input = o.input;
    v.output = o.output;
    v.frames = o.frames;
    v.fps = o.fps;
    v.skip_bad_frames = o.skip_bad_frames;
    v.keyframe_interval = o.keyframe_interval;
    v.roi_file = o.roi_file;
    v.cut_threshold = o.cut_threshold;
    if (!video::parse_flow_method(o.flow, v.flow))
        return make_error(Code::InvalidArgument, "--flow: unknown method '" + o.flow + "' (dis-ultrafast, dis-fast, dis-medium, farneback)");
    v.block_size = o.block_size;
    v.flow_orientation = o.flow_orientation;
    v.max_inter_strokes = o.max_inter_strokes;
    v.paint = o.paint;
    v.paint.rois.clear();  // --roi rectangles apply to every frame; --roi-file ones per frame range
    for (size_t i = 0; i < o.cli_roi_count && i < o.rois.size(); ++i) v.paint.rois.push_back(o.rois[i].rect);
    v.sets = o.sets;
    v.background = o.background;
    v.stored_coding = o.stored;
    v.coding = o.coding;
    v.target_bytes = o.target_bytes;
    v.target_bytes_per_second = o.target_bytes_per_second;
    v.color_encoding = o.color_encoding;
    v.alpha = o.alpha;
    v.scene_read.colorspace = o.colorspace;
    v.scene_read.ocio_config = o.ocio_config;
    v.scene_read.layer = o.layer;
    if (!o.templates_dir.empty()) {
        auto t = io::load_templates(o.templates_dir);
        if (!t) return make_error(Code::InvalidArgument, t.error().message);
        v.templates = std::move(t.value());
    }
    return {};
}


}  // namespace spt::job
