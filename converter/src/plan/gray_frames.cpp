#include "plan/gray_frames.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <thread>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <opencv2/imgproc.hpp>

#include "frames/frame_rate.hpp"
#include "frames/frame_source.hpp"
#include "frames/video_reader.hpp"
#include "io/image_io.hpp"
#include "io/sequence.hpp"
#include "plan/ordered_prefetch.hpp"

namespace spt::plan {

namespace {

// A FrameSource's RGB frames to gray (videos, folders, and files the fast path does not take).
class SourceGray final : public GrayFrames {
public:
    explicit SourceGray(std::unique_ptr<video::FrameSource> s) : src_(std::move(s)) {}
    Result<bool> next(long& number, cv::Mat& gray) override {
        Result<bool> got = src_->next(frame_);
        if (!got || !*got) return got;
        number = frame_.number;
        cv::Mat rgb(int(frame_.image.height), int(frame_.image.width), CV_8UC3, frame_.image.rgb.data());
        cv::cvtColor(rgb, gray, cv::COLOR_RGB2GRAY);
        return true;
    }
    bool has_fps() const override { return src_->has_fps(); }
    Rational fps() const override { return src_->fps(); }
    uint64_t expected_frames() const override { return src_->expected_frames(); }
    std::string shortfall() const override { return src_->shortfall(); }
    std::string describe() const override { return src_->describe(); }

private:
    std::unique_ptr<video::FrameSource> src_;
    video::SourceFrame frame_;
};

// A video file straight to gray: the painter's VideoFileSource (video/frame_source.cpp) reads
// each frame to BGR, swaps it to RGB, copies it out, and the pass made gray of that; here BGR
// goes to gray directly into buffers kept from frame to frame (fresh 6 MB buffers at 1080p cost
// page faults, a quarter of the pass). The same gray: OpenCV weighs the channels in the same
// fixed point whichever order they come in (tested against the painter's reader).
class VideoGray final : public GrayFrames {
public:
    VideoGray(std::string path, io::FrameRange range) : video_(std::move(path), std::move(range)) {}

    Status open() { return video_.open(); }

    Result<bool> next(long& number, cv::Mat& gray) override {
        Result<bool> got = video_.next(number, bgr_);
        if (!got || !*got) return got;
        cv::cvtColor(bgr_, gray_, cv::COLOR_BGR2GRAY);
        if (Status st = video_.check_size(number, gray_.cols, gray_.rows); !st) return st.error();
        gray = gray_;  // shares the buffer: the caller reads it before the next call
        return true;
    }
    bool has_fps() const override { return video_.fps() > 0 && std::isfinite(video_.fps()); }
    Rational fps() const override { return video::fps_from_double(video_.fps()); }
    uint64_t expected_frames() const override { return video_.expected_frames(); }
    std::string shortfall() const override { return video_.shortfall(); }
    std::string describe() const override { return video_.path(); }

private:
    video::VideoReader video_;
    cv::Mat bgr_, gray_;
};

// A decoding thread's buffers, kept from file to file.
struct Scratch {
    std::vector<uint8_t> pixels, rgb;
};

// Reads a 1- or 3-channel file without alpha whose samples are all 8-bit or all half float as
// gray, giving read_image's bytes: 8-bit samples are those bytes, and half samples map through
// read_image's own table (io::half_to_srgb8). False (nothing reported) for any other file,
// which the caller then reads the painter's way.
bool read_gray_direct(const std::string& path, cv::Mat& gray, Scratch& sc) {
    OIIO::ImageSpec hint;
    hint.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &hint);
    if (!in) {
        (void)OIIO::geterror();
        return false;
    }
    const OIIO::ImageSpec& s = in->spec();
    const bool byte = s.format == OIIO::TypeDesc::UINT8;
    bool half = s.format == OIIO::TypeDesc::HALF && io::half_to_srgb8();
    for (const OIIO::TypeDesc& t : s.channelformats) half = half && t == OIIO::TypeDesc::HALF;
    if ((!byte && !half) || (s.nchannels != 1 && s.nchannels != 3) || s.alpha_channel >= 0 || s.deep || s.depth > 1 ||
        s.width <= 0 || s.height <= 0 || int64_t(s.width) * s.height > (int64_t(1) << 28))
        return false;
    const size_t samples = size_t(s.width) * size_t(s.height) * size_t(s.nchannels);
    sc.pixels.resize(samples * (half ? 2 : 1));
    if (!in->read_image(0, 0, 0, s.nchannels, half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::UINT8, sc.pixels.data())) {
        (void)in->geterror();
        return false;
    }
    uint8_t* bytes = sc.pixels.data();
    if (half) {
        const std::array<uint8_t, 65536>& table = *io::half_to_srgb8();
        const auto* h = reinterpret_cast<const uint16_t*>(sc.pixels.data());
        sc.rgb.resize(samples);
        for (size_t i = 0; i < samples; ++i) sc.rgb[i] = table[h[i]];
        bytes = sc.rgb.data();
    }
    cv::Mat m(s.height, s.width, s.nchannels == 3 ? CV_8UC3 : CV_8UC1, bytes);
    if (s.nchannels == 3) cv::cvtColor(m, gray, cv::COLOR_RGB2GRAY);
    else m.copyTo(gray);
    return true;
}

// One frame of a sequence as gray, or what is wrong with it (a function of the file alone, so
// frames can be read on several threads).
struct GrayFile {
    cv::Mat gray;
    std::string problem;
};

GrayFile read_gray_file(const std::string& pattern, long number, const std::string* path, Scratch& sc) {
    GrayFile g;
    if (!path) {
        g.problem = io::format_frame(pattern, number) + ": frame " + std::to_string(number) + " is missing from the sequence";
        return g;
    }
    try {
        if (read_gray_direct(*path, g.gray, sc)) return g;
        // The painter's reader (video/frame_source.cpp): floats, alpha, 16-bit; its messages.
        Result<io::Image> img = io::read_image(*path);
        if (!img) {
            g.problem = img.error().message;
            if (g.problem.find(*path) == std::string::npos) g.problem = *path + ": " + g.problem;
        } else {
            cv::Mat rgb(int(img->height), int(img->width), CV_8UC3, img->rgb.data());
            cv::cvtColor(rgb, g.gray, cv::COLOR_RGB2GRAY);
        }
    } catch (const std::exception& e) {
        g.gray.release();
        g.problem = *path + ": " + e.what();
    }
    return g;
}

class SequenceGray final : public GrayFrames {
public:
    SequenceGray(std::string pattern, std::vector<long> numbers, std::map<long, std::string> files, bool skip, int threads)
        : pattern_(std::move(pattern)), numbers_(std::move(numbers)), files_(std::move(files)), skip_(skip) {
        // Decoding is nearly all of the pass; frames decode on every thread, a few ahead.
        if (threads > 1 && numbers_.size() > 1)
            ahead_ = std::make_unique<Prefetch>(numbers_.size(), threads, size_t(2 * threads),
                                                [this](size_t i, Scratch& sc) { return read(i, sc); });
    }

    Result<bool> next(long& number, cv::Mat& gray) override {
        if (pos_ >= numbers_.size()) return false;
        const size_t i = pos_++;
        number = numbers_[i];
        GrayFile g = ahead_ ? ahead_->take() : read(i, scratch_);
        std::string problem = std::move(g.problem);
        if (problem.empty()) gray = std::move(g.gray);
        if (problem.empty() && !prev_.empty() && gray.size() != prev_.size())
            problem = files_.at(number) + ": frame " + std::to_string(number) + " is " + std::to_string(gray.cols) + "x" +
                      std::to_string(gray.rows) + ", the sequence is " + std::to_string(prev_.cols) + "x" +
                      std::to_string(prev_.rows);
        if (!problem.empty()) {
            if (!skip_ || prev_.empty())
                return make_error(Code::IoError, problem + (skip_ ? " (the first frame cannot be skipped)" : ""));
            prev_.copyTo(gray);  // --skip-bad-frames: the painter repeats the previous frame
            return true;
        }
        gray.copyTo(prev_);
        return true;
    }
    bool has_fps() const override { return false; }
    Rational fps() const override { return {}; }
    uint64_t expected_frames() const override { return numbers_.size(); }
    std::string describe() const override { return pattern_; }

private:
    using Prefetch = OrderedPrefetch<GrayFile, Scratch>;

    GrayFile read(size_t i, Scratch& sc) const {
        auto f = files_.find(numbers_[i]);
        return read_gray_file(pattern_, numbers_[i], f == files_.end() ? nullptr : &f->second, sc);
    }

    std::string pattern_;
    std::vector<long> numbers_;
    std::map<long, std::string> files_;
    bool skip_;
    size_t pos_ = 0;
    cv::Mat prev_;
    Scratch scratch_;
    std::unique_ptr<Prefetch> ahead_;  // last: its threads stop before the members they read go
};

// The files of a sequence pattern and the numbers the painter's SequenceSource walks
// (video/frame_source.cpp).
struct SequenceListing {
    std::vector<long> numbers;
    std::map<long, std::string> files;
};

Result<SequenceListing> list_numbers(const std::string& input, const std::string& frames) {
    Result<io::FrameRange> range = io::parse_frame_range(frames);
    if (!range) return range.error();
    Result<std::vector<io::SequenceFile>> files = io::list_sequence(input, *range);
    if (!files) return files.error();
    if (files->empty()) return make_error(Code::IoError, input + ": no frames found");
    SequenceListing l;
    for (const auto& f : *files) l.files.emplace(f.frame, f.path);
    long first = l.files.begin()->first, last = l.files.rbegin()->first;
    if (!range->empty()) {
        first = range->spans.front().first, last = range->spans.front().second;
        for (const auto& s : range->spans) first = std::min(first, s.first), last = std::max(last, s.second);
    }
    l.numbers = range->frames_within(first, last, 10'000'000);
    return l;
}

class SequenceFiles final : public GrayFrameFiles {
public:
    SequenceFiles(std::string pattern, SequenceListing l) : pattern_(std::move(pattern)), l_(std::move(l)) {}
    size_t count() const override { return l_.numbers.size(); }
    long first() const override { return l_.numbers.front(); }
    Frame read(size_t pos) const override {
        thread_local Scratch sc;
        const long n = l_.numbers[pos];
        auto f = l_.files.find(n);
        GrayFile g = read_gray_file(pattern_, n, f == l_.files.end() ? nullptr : &f->second, sc);
        return Frame{std::move(g.gray), std::move(g.problem)};
    }
    std::string path(size_t pos) const override {
        auto f = l_.files.find(l_.numbers[pos]);
        return f == l_.files.end() ? pattern_ : f->second;
    }
    std::string describe() const override { return pattern_; }

private:
    std::string pattern_;
    SequenceListing l_;
};

}  // namespace

Result<std::unique_ptr<GrayFrameFiles>> open_gray_frame_files(const std::string& input, const std::string& frames) {
    if (!io::is_sequence_pattern(input) || io::is_video_file(input)) return std::unique_ptr<GrayFrameFiles>();
    Result<SequenceListing> l = list_numbers(input, frames);
    if (!l) return l.error();
    // Random access needs consecutive numbers; other ranges are refused by the planner anyway.
    for (size_t i = 1; i < l->numbers.size(); ++i)
        if (l->numbers[i] != l->numbers[i - 1] + 1) return std::unique_ptr<GrayFrameFiles>();
    return std::unique_ptr<GrayFrameFiles>(std::make_unique<SequenceFiles>(input, std::move(*l)));
}

Result<std::unique_ptr<GrayFrames>> open_gray_frames(const std::string& input, const std::string& frames,
                                                     bool skip_bad_frames, int threads) {
    if (threads <= 0) threads = int(std::max(1u, std::thread::hardware_concurrency()));
    if (io::is_sequence_pattern(input) && !io::is_video_file(input)) {
        Result<SequenceListing> l = list_numbers(input, frames);
        if (!l) return l.error();
        return std::unique_ptr<GrayFrames>(std::make_unique<SequenceGray>(input, std::move(l->numbers), std::move(l->files),
                                                                         skip_bad_frames, threads));
    }
    if (io::is_video_file(input)) {
        Result<io::FrameRange> range = io::parse_frame_range(frames);
        if (!range) return range.error();
        auto v = std::make_unique<VideoGray>(input, *range);
        if (Status st = v->open(); !st) return st.error();
        return std::unique_ptr<GrayFrames>(std::move(v));
    }
    Result<std::unique_ptr<video::FrameSource>> src = video::open_source(input, frames, skip_bad_frames);
    if (!src) return src.error();
    return std::unique_ptr<GrayFrames>(std::make_unique<SourceGray>(std::move(*src)));
}

}  // namespace spt::plan
