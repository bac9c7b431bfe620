// Helpers of the video input tests: a temporary folder, and files made with the `ffmpeg`
// command (a test that cannot run it fails: the files are its real part).
#pragma once

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace spt_video_input {

namespace fs = std::filesystem;

struct Dir {
    fs::path path;
    explicit Dir(const std::string& name)
        : path(fs::temp_directory_path() / ("spt_video_input_" + name + "_" + std::to_string(::getpid()))) {
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~Dir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    std::string file(const std::string& name) const { return (path / name).string(); }
};

inline void run_ok(const std::string& cmd) {
    const int st = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(st) && WEXITSTATUS(st) == 0) << "failed: " << cmd;
}

// ffmpeg ARGS OUT, quietly.
inline void make_video(const std::string& out, const std::string& args) {
    run_ok("ffmpeg -v error -nostdin -y " + args + " '" + out + "'");
    ASSERT_TRUE(fs::exists(out)) << out;
}

// A shell command's standard output.
inline std::string capture(const std::string& cmd) {
    std::string out;
    if (FILE* p = ::popen(cmd.c_str(), "r")) {
        char buf[4096];
        size_t n;
        while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
        ::pclose(p);
    }
    return out;
}

}  // namespace spt_video_input
