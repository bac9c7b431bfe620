// Where a rate search (spt paint --target-bytes) codes its trial paintings, only to learn their
// exact size: an spt::AtomicFile beside the output that is never committed. On Linux it has no
// name at all (O_TMPFILE), so no other paint, no user's file and no symlink can meet it, and an
// error, Ctrl-C or a kill leaves nothing; elsewhere it is AtomicFile's exclusively created random
// name, removed when done. spt::Writer takes a path, so path() names the open file through the
// process's descriptor table (/proc/self/fd/N); give it with WriterOptions::atomic_rename false.
#pragma once

#include <string>

#include "spt/atomic_file.hpp"
#include "spt/result.hpp"

namespace spt::io {

class TrialOutput {
public:
    // `output`: the paint's destination (its folder holds the trial; messages name it).
    static Result<TrialOutput> create(const std::string& output);

    // Opening it for writing ("wb") truncates the trial file: one TrialOutput serves every trial.
    const std::string& path() const { return path_; }
    // The trial's name in a message: a Writer's error names path(), which means nothing to a user.
    std::string explain(std::string message) const;
    // Links the trial into place as the output (replacing what is there): the trial won.
    Status keep();

private:
    AtomicFile file_;  // discarded (never committed) when this goes
    std::string output_, path_;
};

}  // namespace spt::io
