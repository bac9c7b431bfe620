#include "video/frame_source.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "video/video_paint.hpp"

namespace spt::video {

namespace {

// Checks a decoded frame against the first one's size.
bool same_size(const io::Image& a, const io::Image& b) { return a.width == b.width && a.height == b.height; }
bool same_size(const io::SceneImage& a, const io::SceneImage& b) { return a.width == b.width && a.height == b.height; }

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
            Result<io::SceneImage> img = io::read_scene_image(path, scene_opts_);
            if (!img) {
                problem = img.error().message;
                if (problem.find(path) == std::string::npos) problem = path + ": " + problem;
            } else if (have_prev_ && !same_size(*img, prev_scene_)) {
                problem = path + ": frame " + std::to_string(n) + " is " + std::to_string(img->width) + "x" +
                          std::to_string(img->height) + ", the sequence is " + std::to_string(prev_scene_.width) +
                          "x" + std::to_string(prev_scene_.height);
            } else {
                out.scene = std::move(*img);
            }
        } else {
            Result<io::Image> img = io::read_image(path);
            if (!img) {
                problem = img.error().message;
                if (problem.find(path) == std::string::npos) problem = path + ": " + problem;
            } else if (have_prev_ && !same_size(*img, prev_)) {
                problem = path + ": frame " + std::to_string(n) + " is " + std::to_string(img->width) + "x" +
                          std::to_string(img->height) + ", the sequence is " + std::to_string(prev_.width) +
                          "x" + std::to_string(prev_.height);
            } else {
                out.image = std::move(*img);
            }
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
    VideoFileSource(std::string path, io::FrameRange range) : path_(std::move(path)), range_(std::move(range)) {}

    Status open() {
        if (!cap_.open(path_)) return make_error(Code::IoError, path_ + ": OpenCV cannot open this video file");
        fps_ = cap_.get(cv::CAP_PROP_FPS);
        const double n = cap_.get(cv::CAP_PROP_FRAME_COUNT);
        total_ = n > 0 && n < 1e9 ? uint64_t(n) : 0;
        if (!range_.empty()) {
            last_wanted_ = range_.spans.front().second;
            for (const auto& s : range_.spans) last_wanted_ = std::max(last_wanted_, s.second);
        }
        return {};
    }

    Result<bool> next(SourceFrame& out) override {
        cv::Mat bgr;
        for (;;) {
            if (!range_.empty() && pos_ > last_wanted_) return false;
            if (!range_.empty() && !range_.contains(pos_)) {
                if (!cap_.grab()) return false;  // skip without decoding to RGB
                ++pos_;
                continue;
            }
            if (!cap_.read(bgr) || bgr.empty()) return false;
            break;
        }
        out = SourceFrame{};
        out.number = pos_++;
        if (bgr.depth() != CV_8U) bgr.convertTo(bgr, CV_8U);
        cv::Mat rgb;
        if (bgr.channels() == 1) cv::cvtColor(bgr, rgb, cv::COLOR_GRAY2RGB);
        else if (bgr.channels() == 4) cv::cvtColor(bgr, rgb, cv::COLOR_BGRA2RGB);
        else cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
        if (width_ == 0) { width_ = rgb.cols; height_ = rgb.rows; }
        if (rgb.cols != width_ || rgb.rows != height_)
            return make_error(Code::Corrupt, path_ + ": frame " + std::to_string(out.number) + " changes size");
        out.image.width = uint32_t(rgb.cols);
        out.image.height = uint32_t(rgb.rows);
        out.image.rgb.assign(rgb.data, rgb.data + rgb.total() * 3);
        return true;
    }
    bool has_fps() const override { return fps_ > 0 && std::isfinite(fps_); }
    Rational fps() const override { return fps_from_double(fps_); }
    uint64_t expected_frames() const override { return range_.count_in_video(total_); }
    std::string describe() const override { return path_; }

private:
    std::string path_;
    io::FrameRange range_;
    cv::VideoCapture cap_;
    double fps_ = 0;
    uint64_t total_ = 0;
    long pos_ = 0, last_wanted_ = 0;
    int width_ = 0, height_ = 0;
};

}  // namespace

Result<std::unique_ptr<FrameSource>> open_source(const std::string& input, const std::string& frames,
                                                 bool skip_bad_frames, const io::SceneReadOptions* scene) {
    Result<io::FrameRange> range = io::parse_frame_range(frames);
    if (!range) return range.error();
    if (io::is_video_file(input)) {
        if (scene)
            return make_error(Code::InvalidArgument, input + ": alpha and scene-linear painting needs an image "
                                                             "sequence (EXR, PNG, TIFF), not a video file");
        auto src = std::make_unique<VideoFileSource>(input, *range);
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

}  // namespace spt::video
