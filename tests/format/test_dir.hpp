// The file-writing tests' fixtures: a temporary folder of one test (removed with it), the bytes
// of a file, and the smallest stream a Writer takes.
#pragma once

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "spt/spt.hpp"

namespace spt::testing {

struct TestDir {
    std::filesystem::path path;
    TestDir() {
        const auto* t = ::testing::UnitTest::GetInstance()->current_test_info();
        path = std::filesystem::temp_directory_path() /
               ("spt_test_" + std::to_string(::getpid()) + "_" + t->test_suite_name() + "_" + t->name());
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~TestDir() { std::error_code ec; std::filesystem::remove_all(path, ec); }
    TestDir(const TestDir&) = delete;
    TestDir& operator=(const TestDir&) = delete;
    std::string operator/(const std::string& n) const { return (path / n).string(); }
    // The names in the folder, sorted: what a test left on disk.
    std::vector<std::string> names() const {
        std::vector<std::string> v;
        for (const auto& e : std::filesystem::directory_iterator(path)) v.push_back(e.path().filename().string());
        std::sort(v.begin(), v.end());
        return v;
    }
};

inline std::string slurp(const std::string& p) {
    std::ifstream f(p, std::ios::binary);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

// An 8x8 canvas, one stroke set, four orientations, one ellipse template.
inline StreamInfo small_info() {
    StreamInfo info;
    info.header.width = 8;
    info.header.height = 8;
    info.header.sets = {{4, 2}};
    info.header.orientations = default_orientations(4);
    Template e;
    e.kind = TemplateKind::Ellipse;
    info.templates = {e};
    return info;
}

}  // namespace spt::testing
