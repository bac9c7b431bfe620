#include "io/private_output.hpp"

#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "spt/atomic_file.hpp"

namespace spt::io {

namespace fs = std::filesystem;

PrivateOutput& PrivateOutput::operator=(PrivateOutput&& o) noexcept {
    if (this != &o) {
        discard();
        path_ = std::move(o.path_);
        dir_ = std::move(o.dir_);
        file_ = std::move(o.file_);
        o.dir_.clear();
    }
    return *this;
}

Result<PrivateOutput> PrivateOutput::create(const std::string& path) {
    if (Status c = check_output_path(path); !c) return c.error();
    const fs::path parent = fs::path(path).parent_path();
    std::string templ = (parent.empty() ? fs::path(".spt-XXXXXX") : parent / ".spt-XXXXXX").string();
    if (!::mkdtemp(templ.data()))
        return make_error(Code::IoError, path + ": cannot create a private folder beside it: " + std::strerror(errno));
    PrivateOutput p;
    p.path_ = path;
    p.dir_ = templ;
    p.file_ = (fs::path(templ) / fs::path(path).filename()).string();
    return p;
}

Status PrivateOutput::check_space() const {
    const std::string probe = (fs::path(dir_) / ".space").string();
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
    if (fd < 0) return make_error(Code::IoError, path_ + ": " + std::strerror(errno));
    static const char zeros[65536] = {};
    int err = 0;
    size_t done = 0;
    while (done < sizeof zeros && err == 0) {
        const ssize_t n = ::write(fd, zeros + done, sizeof zeros - done);
        if (n < 0) err = errno;
        else done += size_t(n);
    }
    if (err == 0 && ::fsync(fd) != 0) err = errno;
    ::close(fd);
    ::unlink(probe.c_str());
    if (err) return make_error(Code::IoError, path_ + ": " + std::strerror(err));
    return {};
}

Status PrivateOutput::commit() {
    std::error_code ec;
    fs::rename(file_, path_, ec);
    const std::string why = ec ? ec.message() : std::string();
    discard();
    if (!why.empty()) return make_error(Code::IoError, path_ + ": cannot move the finished file into place: " + why);
    return {};
}

void PrivateOutput::discard() {
    if (dir_.empty()) return;
    std::error_code ec;
    fs::remove_all(dir_, ec);
    dir_.clear();
}

}  // namespace spt::io
