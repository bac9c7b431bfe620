// For writers that need a file name (OpenCV's video writer, an OpenImageIO plugin without
// IOProxy output): a fresh folder created with mkdtemp (mode 0700, a name nobody else chose)
// beside the destination; the writer writes inside it, commit() renames the file into place and
// removes the folder. Nothing at a guessable name is opened, so nothing can be redirected; a
// killed process leaves the folder ".spt-XXXXXX" (spt::AtomicFile is preferred where possible).
#pragma once

#include <string>

#include "spt/result.hpp"

namespace spt::io {

class PrivateOutput {
public:
    // Checks `path` (spt::check_output_path) and makes the folder.
    static Result<PrivateOutput> create(const std::string& path);
    PrivateOutput() = default;
    PrivateOutput(PrivateOutput&& o) noexcept { *this = std::move(o); }
    PrivateOutput& operator=(PrivateOutput&& o) noexcept;
    ~PrivateOutput() { discard(); }

    // Where the writer writes: inside the private folder, with the destination's file name.
    const std::string& file() const { return file_; }
    // Whether the folder's file system still takes 64 KiB (written and synced, then removed):
    // a writer that reports no errors of its own (OpenCV's video writer) fails silently when
    // the disk fills, and leaves less than its buffer free. The error names the destination
    // and the system's reason ("No space left on device").
    Status check_space() const;
    // Moves file() to the destination (replacing a symlink there, never following it).
    Status commit();
    void discard();

private:
    std::string path_, dir_, file_;
};

}  // namespace spt::io
