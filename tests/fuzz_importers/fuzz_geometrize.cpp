// libFuzzer target: the geometrize-json importer (and its text parser) on arbitrary bytes. It must
// return a value or an error, never crash, hang or allocate hugely.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "spt_import/importer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const spt::import::Importer* imp = spt::import::find_importer("geometrize-json");
    spt::import::ImportOptions opts;
    // Small limits keep each run fast; the importer checks them before allocating.
    opts.limits.max_width = opts.limits.max_height = 4096;
    opts.limits.max_pixels = 1u << 20;
    opts.limits.max_strokes_per_frame = 1u << 16;
    opts.canvas_size = std::make_pair(64u, 48u);
    auto r = imp->load("fuzz-input", std::string_view(reinterpret_cast<const char*>(data), size), opts);
    (void)r;
    return 0;
}
