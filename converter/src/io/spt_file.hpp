// Helpers the spt commands share for .spt files: opening with readable errors.
#pragma once

#include <memory>
#include <string>
#include <vector>

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

// What spt verify checks of the frames a command reads whole (spt export), through the reader's
// own path: the header and templates make a renderer; every frame at `positions` is decoded and
// applied by strokes_at (removals and motion in range, the live list within the limits and the
// rendering work of SPEC.md 10); a file with no frame fails. Frames lost to damage (a skipped
// index, a cut) fail it when `lost_matter` (the command wants every frame, or some past the
// last one found); damage that costs nothing asked for is added to `warnings`, described.
Status check_frames(Reader& r, const std::string& path, const std::vector<size_t>& positions, bool lost_matter,
                    std::vector<std::string>& warnings);

}  // namespace spt::io
