#include "cartoon/memory_bound.hpp"

#include <cstdio>

namespace spt::cartoon {

std::string gib(uint64_t bytes) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f GiB", double(bytes) / double(1ull << 30));
    return buf;
}

Status check_memory(const std::string& file, uint64_t width, uint64_t height, uint64_t bytes_per_pixel,
                    uint64_t max_memory) {
    if (max_memory == 0) return {};
    // width and height are at most 2^32 each and bytes_per_pixel small: no overflow in 128 bits.
    const unsigned __int128 need = (unsigned __int128)width * height * bytes_per_pixel;
    if (need <= max_memory) return {};
    const uint64_t shown = need > ~uint64_t(0) ? ~uint64_t(0) : uint64_t(need);
    return make_error(Code::LimitExceeded,
                      file + ": " + std::to_string(width) + "x" + std::to_string(height) + " is too large for --style cartoon "
                      "within --max-memory " + gib(max_memory) + " (it takes about " + std::to_string(bytes_per_pixel) +
                      " bytes a pixel, " + gib(shown) + "); give a larger --max-memory or a smaller input");
}

}  // namespace spt::cartoon
