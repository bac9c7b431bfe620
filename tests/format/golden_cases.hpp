// The cases of the golden conformance files (tests/format/golden/, SPEC.md 9.4): a stroke stream
// each, and how make_golden writes it.
#pragma once

#include <string>
#include <vector>

#include "format/coding_random_streams.hpp"

namespace spt::testing::golden {

struct Case {
    std::string name;
    std::string about;
    RandomStream stream;
    bool drop_index = false;           // rewrite without indx (IEND index_offset 0)
    bool unknown_ancillary = false;    // insert an unknown ancillary chunk after HEAD
    bool replay = false;               // <name>.spt in frame coding 2 (every frame must replay)
};

// Every case, in the order of MANIFEST.txt.
std::vector<Case> cases();

}  // namespace spt::testing::golden
