// A temporary folder for one test, named after it and removed with it: the format tests'
// TestDir, with the `file(name)` spelling the converter tests use.
#pragma once

#include <string>

#include "format/test_dir.hpp"

namespace spt_test {

struct TempDir : spt::testing::TestDir {
    std::string file(const std::string& name) const { return *this / name; }
};

}  // namespace spt_test
