// What a farm plan's tasks decode of one video file (issue 37): the file split into T tasks of
// consecutive frames, each read by the painter's video reader (frames/video_reader.hpp) from its
// own range, as `spt paint --plan` does. Prints the frames decoded over the plan against the
// frames (the goal: at most 1.1x) and the time.
//
//   build/bench/video_seek_bench [FILE [TASKS]]
//
// Without FILE it makes a 2,000-frame 640x360 H.264 file (key frame every 24 frames, B-frames)
// in the temp folder with the `ffmpeg` command. TASKS defaults to 20.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <opencv2/core.hpp>

#include "io/sequence.hpp"
#include "frames/ffmpeg_video.hpp"
#include "frames/video_reader.hpp"

int main(int argc, char** argv) {
    namespace fs = std::filesystem;
    std::string file = argc > 1 ? argv[1] : "";
    const int tasks = argc > 2 ? std::atoi(argv[2]) : 20;
    if (file.empty()) {
        file = (fs::temp_directory_path() / "spt_video_seek_bench_2000.mp4").string();
        if (!fs::exists(file)) {
            const std::string cmd = "ffmpeg -v error -nostdin -y -f lavfi -i testsrc2=s=640x360:r=24 -frames:v 2000 "
                                    "-c:v libx264 -g 24 -bf 2 -pix_fmt yuv420p '" + file + "'";
            if (std::system(cmd.c_str()) != 0) {
                std::fprintf(stderr, "video_seek_bench: cannot make %s with ffmpeg\n", file.c_str());
                return 1;
            }
        }
    }
    spt::Result<uint64_t> n = spt::video::count_video_packets(file);
    if (!n) {
        std::fprintf(stderr, "video_seek_bench: %s\n", n.error().message.c_str());
        return 1;
    }
    const long frames = long(*n);
    uint64_t decoded = 0, delivered = 0, from_start = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (int t = 0; t < tasks; ++t) {
        const long a = frames * t / tasks, b = frames * (t + 1) / tasks - 1;
        spt::Result<spt::io::FrameRange> range = spt::io::parse_frame_range(std::to_string(a) + "-" + std::to_string(b));
        spt::video::VideoReader r(file, *range);
        if (spt::Status st = r.open(); !st) {
            std::fprintf(stderr, "video_seek_bench: %s\n", st.error().message.c_str());
            return 1;
        }
        long number = 0;
        cv::Mat frame;
        while (true) {
            spt::Result<bool> got = r.next(number, frame);
            if (!got) {
                std::fprintf(stderr, "video_seek_bench: %s\n", got.error().message.c_str());
                return 1;
            }
            if (!*got) break;
            ++delivered;
        }
        decoded += r.decoded_frames();
        from_start += uint64_t(b + 1);  // what a reader that cannot seek decodes
    }
    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%s: %ld frames in %d tasks\n", file.c_str(), frames, tasks);
    std::printf("delivered %llu, decoded %llu (%.3fx the frames; decoding from the start: %llu, %.2fx)\n",
                (unsigned long long)delivered, (unsigned long long)decoded, double(decoded) / double(frames),
                (unsigned long long)from_start, double(from_start) / double(frames));
    std::printf("time %.2f s (%.2f ms a frame delivered)\n", sec, 1000.0 * sec / double(std::max<uint64_t>(1, delivered)));
    return decoded <= uint64_t(1.1 * double(frames)) ? 0 : 2;
}
