#include "frames/frame_source.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "frames/frame_rate.hpp"
#include "frames/video_reader.hpp"
#include "frames/video_scene.hpp"

namespace spt::video {

namespace {

// Frame `n` of a sequence, read from `path` by `read` (8-bit or scene-linear) into `out`; else
// `problem` says why not: the reader's error (naming the file), or a size other than `prev`'s,
// the previous frame's, when there is one.
template <class Image, class Read>
void read_sequence_frame(const Read& read, const std::string& path, long n, const Image* prev, Image& out,
                         std::string& problem) {
    Result<Image> img = read(path);
    if (!img) {
        problem = img.error().message;
        if (problem.find(path) == std::string::npos) problem = path + ": " + problem;
    } else if (prev && (img->width != prev->width || img->height != prev->height)) {
        problem = path + ": frame " + std::to_string(n) + " is " + std::to_string(img->width) + "x" +
                  std::to_string(img->height) + ", the sequence is " + std::to_string(prev->width) + "x" +
                  std::to_string(prev->height);
    } else {
        out = std::move(*img);
    }
}

class SequenceSource final : public FrameSource {
public:
    SequenceSource(std::string pattern, std::vector<long> numbers, std::map<long, std::string> files,
                   bool skip, const io::SceneReadOptions* scene)
        : pattern_(std::move(pattern)), numbers_(std::move(numbers)), files_(std::move(files)), skip_(skip),
          scene_(scene != nullptr) {
        if (scene) scene_opts_ = *scene;
    }

    Result<bool> next(SourceFrame& out) override {
        if (pos_ >= numbers_.size()) return false;
        const long n = numbers_[pos_++];
        out = SourceFrame{};
        out.number = n;
        std::string problem;
        auto f = files_.find(n);
        const std::string path = f != files_.end() ? f->second : io::format_frame(pattern_, n);
        if (f == files_.end()) {
            problem = path + ": frame " + std::to_string(n) + " is missing from the sequence";
        } else if (scene_) {
            read_sequence_frame([&](const std::string& p) { return io::read_scene_image(p, scene_opts_); }, path, n,
                                have_prev_ ? &prev_scene_ : nullptr, out.scene, problem);
        } else {
            read_sequence_frame([](const std::string& p) { return io::read_image(p); }, path, n,
                                have_prev_ ? &prev_ : nullptr, out.image, problem);
        }
        if (!problem.empty()) {
            // The first frame has nothing to repeat, so it must be sound even when skipping.
            if (!skip_ || !have_prev_)
                return make_error(Code::IoError, problem + (skip_ ? " (the first frame cannot be skipped)" : ""));
            out.image = prev_;
            out.scene = prev_scene_;
            out.repeated = true;
            out.problem = problem;
            return true;
        }
        if (scene_) prev_scene_ = out.scene;
        else prev_ = out.image;
        have_prev_ = true;
        return true;
    }
    uint64_t expected_frames() const override { return numbers_.size(); }
    std::string describe() const override { return pattern_; }

private:
    std::string pattern_;
    std::vector<long> numbers_;
    std::map<long, std::string> files_;
    bool skip_;
    size_t pos_ = 0;
    io::Image prev_;
    bool scene_ = false;
    io::SceneReadOptions scene_opts_;
    io::SceneImage prev_scene_;
    bool have_prev_ = false;
};

class VideoFileSource final : public FrameSource {
public:
    VideoFileSource(std::string path, io::FrameRange range, const io::SceneReadOptions* scene)
        : video_(std::move(path), std::move(range)), scene_(scene != nullptr) {
        if (scene) scene_opts_ = *scene;
    }

    Status open() { return video_.open(); }

    Result<bool> next(SourceFrame& out) override {
        long number = 0;
        Result<bool> got = video_.next(number, bgr_, scene_ && video_.deep());
        if (!got || !*got) return got;
        out = SourceFrame{};
        out.number = number;
        if (Status st = video_.check_size(number, bgr_.cols, bgr_.rows); !st) return st.error();
        if (scene_) {
            Result<io::SceneImage> img = scene_from_frame(bgr_, video_.has_alpha(), video_.bit_depth(), scene_opts_,
                                                            video_.path());
            if (!img) return img.error();
            out.scene = std::move(*img);
            return true;
        }
        cv::Mat rgb;
        cv::cvtColor(bgr_, rgb, cv::COLOR_BGR2RGB);
        out.image.width = uint32_t(rgb.cols);
        out.image.height = uint32_t(rgb.rows);
        out.image.rgb.assign(rgb.data, rgb.data + rgb.total() * 3);
        return true;
    }
    bool has_fps() const override { return video_.fps() > 0 && std::isfinite(video_.fps()); }
    Rational fps() const override { return fps_from_double(video_.fps()); }
    uint64_t expected_frames() const override { return video_.expected_frames(); }
    std::string shortfall() const override { return video_.shortfall(); }
    std::string describe() const override { return video_.path(); }

private:
    VideoReader video_;
    bool scene_ = false;
    io::SceneReadOptions scene_opts_;
    cv::Mat bgr_;
};

}  // namespace

Result<std::unique_ptr<FrameSource>> open_source(const std::string& input, const std::string& frames,
                                                 bool skip_bad_frames, const io::SceneReadOptions* scene) {
    Result<io::FrameRange> range = io::parse_frame_range(frames);
    if (!range) return range.error();
    if (io::is_video_file(input)) {
        auto src = std::make_unique<VideoFileSource>(input, *range, scene);
        Status st = src->open();
        if (!st) return st.error();
        return std::unique_ptr<FrameSource>(std::move(src));
    }
    Result<std::vector<io::SequenceFile>> files = io::list_sequence(input, *range);
    if (!files) return files.error();
    if (files->empty()) return make_error(Code::IoError, input + ": no frames found");
    std::map<long, std::string> by_number;
    for (const auto& f : *files) by_number.emplace(f.frame, f.path);
    // Frames expected: every number of the requested range, or from the first to the last
    // frame found; the gaps are missing frames (an error, or repeats with --skip-bad-frames).
    std::vector<long> numbers;
    const long lo = by_number.begin()->first, hi = by_number.rbegin()->first;
    const bool pattern = io::is_sequence_pattern(input);
    if (pattern && !range->empty()) {
        long first = range->spans.front().first, last = range->spans.front().second;
        for (const auto& s : range->spans) first = std::min(first, s.first), last = std::max(last, s.second);
        numbers = range->frames_within(first, last, 10'000'000);
    } else if (pattern) {
        numbers = range->frames_within(lo, hi, 10'000'000);
    } else {
        for (const auto& [n, p] : by_number) numbers.push_back(n);
    }
    return std::unique_ptr<FrameSource>(
        std::make_unique<SequenceSource>(input, std::move(numbers), std::move(by_number), skip_bad_frames, scene));
}

bool frames_consecutive(const std::string& frames) {
    Result<io::FrameRange> r = io::parse_frame_range(frames);
    return r && (r->empty() || (r->spans.size() == 1 && r->step(0) == 1));
}

}  // namespace spt::video
