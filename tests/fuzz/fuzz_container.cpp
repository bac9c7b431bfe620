// Fuzz target: a whole file through Reader::open_memory, then every frame decoded and applied.
#include <cstddef>
#include <cstdint>

#include "spt/spt.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    spt::ReaderOptions ro;
    // Checksums off, so that mutations reach the frame decoders (CRC checking itself is covered
    // by the bit-flip tests); every decoder must survive unchecked bytes anyway.
    ro.verify_checksums = false;
    // Small limits keep a fuzzer's memory bounded; the checks are the same at any size.
    ro.limits.max_width = ro.limits.max_height = 4096;
    ro.limits.max_pixels = 1u << 22;
    ro.limits.max_strokes_per_frame = ro.limits.max_live_strokes = 1u << 14;
    ro.limits.max_curve_points = 1u << 10;
    auto r = spt::Reader::open_memory(data, size, ro);
    if (!r) return 0;
    for (size_t i = 0; i < (*r)->frames().size(); ++i) {
        (void)(*r)->field_stats(i);
        if (!(*r)->strokes_at(i)) break;
    }
    return 0;
}
