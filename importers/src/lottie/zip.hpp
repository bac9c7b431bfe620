// The animation JSON inside a .lottie archive.
#pragma once

#include <string>

#include "spt/result.hpp"

namespace spt::import::lottie {

// The first animation the manifest names (or the first animations/*.json), at most `cap` bytes.
Result<std::string> dotlottie_animation(const std::string& path, size_t cap);

}  // namespace spt::import::lottie
