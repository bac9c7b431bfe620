// Fuzz target: the converter's --roi-file parser (io/roi_file.cpp over the importers' JSON
// parser) on arbitrary bytes. It must return ROIs or an error, never crash or hang.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "io/roi_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    auto r = spt::io::parse_roi_json(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz-input");
    (void)r;
    return 0;
}
