// Output files that appear under their final name only when complete, and whose temporary form
// cannot be redirected. On Linux the file is created unnamed (O_TMPFILE) in the destination
// folder and linked into place by commit(): a killed process leaves nothing behind. Elsewhere
// (or on a file system without O_TMPFILE) it is created exclusively (O_CREAT | O_EXCL |
// O_NOFOLLOW) under a random name beside the destination and renamed into place; only a kill
// between creation and commit leaves that name (".NAME.XXXXXXXXXXXX.tmp") behind. No existing
// path is ever opened for writing, so a symlink at a temporary name is never followed; a
// symlink at the final name is replaced, not written through. See SECURITY.md.
#pragma once

#include <cstddef>
#include <cstdio>
#include <string>

#include "spt/result.hpp"

namespace spt {

class AtomicFile {
public:
    // Creates the temporary in the folder of `path`. Fails (naming `path`) when the folder is
    // missing or not writable, or when `path` is a folder. `allow_unnamed` false takes the
    // named fallback even where O_TMPFILE works (its tests use it).
    static Result<AtomicFile> create(const std::string& path, bool allow_unnamed = true);

    AtomicFile() = default;
    AtomicFile(AtomicFile&& o) noexcept { *this = std::move(o); }
    AtomicFile& operator=(AtomicFile&& o) noexcept;
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;
    ~AtomicFile() { discard(); }

    // The open temporary, readable and writable (seeking is fine); null after commit/discard.
    std::FILE* stream() const { return file_; }
    const std::string& path() const { return path_; }
    // True when the temporary has no name (nothing to clean up after a crash).
    bool unnamed() const { return temp_.empty(); }

    // Flushes, closes and links the file at path(), replacing whatever was there atomically.
    Status commit();
    // Closes and removes the temporary; path() is untouched. Idempotent.
    void discard();

private:
    std::string path_, temp_;  // temp_: the random name, empty when unnamed
    std::FILE* file_ = nullptr;
};

// Writes `size` bytes to `path` through an AtomicFile.
Status write_file_atomic(const std::string& path, const void* data, size_t size);

// Checks that `path` could be written, without leaving anything: not a folder, its folder
// exists and takes new files. Lets a command refuse before hours of work rather than after.
Status check_output_path(const std::string& path);

}  // namespace spt
