// What the cartoon painter takes per pixel of its input, and the up-front refusal of an input
// it cannot paint within a budget (--max-memory): a process killed by the kernel half-way says
// nothing, a refusal names the file, its size and the budget.
#pragma once

#include <cstdint>
#include <string>

#include "spt/result.hpp"

namespace spt::cartoon {

// Bytes per input pixel, rounded up from peak RSS (/usr/bin/time -v) of one-colour 1024x1024
// and 2048x2048 PNGs with --target-psnr 40, the marginal cost between the two (a one-colour
// image is the worst case: its one region is traced on the whole image): a still traces on
// 8x8 sub-pixels (164 B/px measured: the sub-pixel mask and the contour finder's bordered
// copy of it, 64 each, and the per-pixel fields), a sequence on 4x4 (104 B/px, two frames'
// images and canvases besides).
constexpr uint64_t kStillBytesPerPixel = 192;
constexpr uint64_t kSequenceBytesPerPixel = 128;
// The default budget: 8 GiB, 2^28 pixels (the readers' limit) would need 48 GiB as a still.
constexpr uint64_t kDefaultMaxMemory = 8ull << 30;

// Fails (Code::LimitExceeded) naming `file`, its size, the estimate and the budget when a
// width x height frame at `bytes_per_pixel` would need more than `max_memory` bytes; 0: no bound.
Status check_memory(const std::string& file, uint64_t width, uint64_t height, uint64_t bytes_per_pixel,
                    uint64_t max_memory);

// "1.50 GiB" for a byte count (messages).
std::string gib(uint64_t bytes);

}  // namespace spt::cartoon
