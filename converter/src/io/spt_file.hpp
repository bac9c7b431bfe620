// Helpers the spt commands share for .spt files: opening with readable errors.
#pragma once

#include <memory>
#include <string>

#include "spt/reader.hpp"
#include "spt/result.hpp"

namespace spt::io {

// "<path>: <message>" with " (byte offset N)" appended when the error has an offset that the
// message does not already state.
std::string describe_error(const std::string& path, const Error& e);

// Opens a .spt file; a missing file or a folder is reported before libspt sees it.
// Errors from here are already described (message starts with the path).
Result<std::unique_ptr<Reader>> open_spt(const std::string& path, const ReaderOptions& opts = {});

// Whole-file rendering checks share this: frames()[pos] as "frame I (byte offset O)".
std::string frame_place(const Reader& r, size_t pos);
// An error met while decoding frame `pos`: described, and placed with frame_place() unless the
// library's message already names the frame.
std::string frame_error(const Reader& r, size_t pos, const std::string& path, const Error& e);

}  // namespace spt::io
