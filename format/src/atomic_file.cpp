// AtomicFile (spt/atomic_file.hpp): O_TMPFILE + linkat on Linux; O_CREAT | O_EXCL | O_NOFOLLOW
// under a random name elsewhere; C's exclusive "wbx" where POSIX is missing.
#include "spt/atomic_file.hpp"

#include <cerrno>
#include <cstring>
#include <random>

#if defined(__unix__) || defined(__APPLE__)
#define SPT_POSIX 1
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

namespace spt {

namespace {

Error io_error(const std::string& path, const std::string& what, int err) {
    return make_error(Code::IoError, path + ": " + what + (err ? std::string(": ") + std::strerror(err) : std::string()));
}

std::string folder_of(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    if (slash == std::string::npos) return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

std::string random_name_beside(const std::string& path) {
    static const char* digits = "0123456789abcdefghijklmnopqrstuvwxyz";
    thread_local std::mt19937_64 rng{std::random_device{}()};
    std::string r;
    for (int i = 0; i < 12; ++i) r += digits[rng() % 36];
    const size_t slash = path.find_last_of('/');
    const std::string dir = slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
    const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
    return dir + "." + base + "." + r + ".tmp";
}

#ifdef SPT_POSIX
bool is_folder(const std::string& path) {
    struct stat st;
    return ::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

// Opens a new file under a fresh random name; never an existing path, never through a symlink.
int open_exclusive(const std::string& path, std::string& name) {
    for (int attempt = 0; attempt < 64; ++attempt) {
        name = random_name_beside(path);
        const int fd = ::open(name.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (fd >= 0 || errno != EEXIST) return fd;
    }
    errno = EEXIST;
    return -1;
}
#endif

}  // namespace

AtomicFile& AtomicFile::operator=(AtomicFile&& o) noexcept {
    if (this != &o) {
        discard();
        path_ = std::move(o.path_);
        temp_ = std::move(o.temp_);
        file_ = o.file_;
        o.file_ = nullptr;
        o.temp_.clear();
    }
    return *this;
}

Result<AtomicFile> AtomicFile::create(const std::string& path, bool allow_unnamed) {
    AtomicFile a;
    a.path_ = path;
    if (path.empty() || path.back() == '/') return io_error(path, "is a folder, not a file name", 0);
#ifdef SPT_POSIX
    if (is_folder(path)) return io_error(path, "is a folder, not a file name", 0);
    const std::string dir = folder_of(path);
    int fd = -1;
#if defined(__linux__) && defined(O_TMPFILE)
    if (allow_unnamed) {
        fd = ::open(dir.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0666);
        // EISDIR: a kernel without O_TMPFILE; EOPNOTSUPP: a file system without it.
        if (fd < 0 && errno != EISDIR && errno != EOPNOTSUPP && errno != EINVAL)
            return io_error(path, "cannot create a file in " + dir, errno);
    }
#else
    (void)allow_unnamed;
#endif
    if (fd < 0) {
        fd = open_exclusive(path, a.temp_);
        if (fd < 0) {
            const int e = errno;
            a.temp_.clear();
            return io_error(path, "cannot create a file in " + dir, e);
        }
    }
    a.file_ = ::fdopen(fd, "w+b");
    if (!a.file_) {
        const int e = errno;
        ::close(fd);
        if (!a.temp_.empty()) ::unlink(a.temp_.c_str());
        a.temp_.clear();
        return io_error(path, "cannot open a stream", e);
    }
#else
    for (int attempt = 0; attempt < 64 && !a.file_; ++attempt) {
        a.temp_ = random_name_beside(path);
        a.file_ = std::fopen(a.temp_.c_str(), "w+bx");
    }
    if (!a.file_) {
        a.temp_.clear();
        return io_error(path, "cannot create a file beside it", errno);
    }
#endif
    return a;
}

Status AtomicFile::commit() {
    if (!file_) return io_error(path_, "nothing to commit (already committed or discarded)", 0);
    if (std::fflush(file_) != 0) {
        const int e = errno;
        discard();
        return io_error(path_, "cannot write", e);
    }
#ifdef SPT_POSIX
    if (temp_.empty()) {
        // Unnamed: give it the final name directly when that is free, else a fresh random name
        // (linkat never replaces, never follows a symlink at its target) renamed over it.
        const std::string self = "/proc/self/fd/" + std::to_string(::fileno(file_));
        auto link_as = [&](const std::string& name) {
            if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, name.c_str(), AT_SYMLINK_FOLLOW) == 0) return true;
#ifdef AT_EMPTY_PATH
            // Without /proc mounted (needs CAP_DAC_READ_SEARCH, so usually as root only).
            if (errno == ENOENT && ::linkat(::fileno(file_), "", AT_FDCWD, name.c_str(), AT_EMPTY_PATH) == 0) return true;
#endif
            return false;
        };
        bool linked = link_as(path_);
        if (!linked && errno == EEXIST) {
            std::string name;
            for (int attempt = 0; attempt < 64 && !linked; ++attempt) {
                name = random_name_beside(path_);
                linked = link_as(name);
                if (!linked && errno != EEXIST) break;
            }
            if (linked && ::rename(name.c_str(), path_.c_str()) != 0) {
                const int e = errno;
                ::unlink(name.c_str());
                discard();
                return io_error(path_, is_folder(path_) ? "is a folder, not a file name" : "cannot move the finished file into place", is_folder(path_) ? 0 : e);
            }
        }
        if (!linked) {
            const int e = errno;
            discard();
            return io_error(path_, "cannot link the finished file into place", e);
        }
        const int rc = std::fclose(file_);
        file_ = nullptr;
        if (rc != 0) return io_error(path_, "cannot close", errno);
        return {};
    }
#endif
    const int rc = std::fclose(file_);
    file_ = nullptr;
    if (rc != 0) {
        const int e = errno;
        std::remove(temp_.c_str());
        temp_.clear();
        return io_error(path_, "cannot close", e);
    }
#ifndef SPT_POSIX
    std::remove(path_.c_str());  // rename does not replace there
#endif
    if (std::rename(temp_.c_str(), path_.c_str()) != 0) {
        const int e = errno;
        std::remove(temp_.c_str());
        temp_.clear();
        return io_error(path_, "cannot move the finished file into place", e);
    }
    temp_.clear();
    return {};
}

void AtomicFile::discard() {
    if (file_) {
        std::fclose(file_);
        file_ = nullptr;
    }
    if (!temp_.empty()) {
        std::remove(temp_.c_str());
        temp_.clear();
    }
}

Status write_file_atomic(const std::string& path, const void* data, size_t size) {
    auto f = AtomicFile::create(path);
    if (!f) return f.error();
    if (size && std::fwrite(data, 1, size, f->stream()) != size) {
        const int e = errno;
        f->discard();
        return io_error(path, "write failed", e);
    }
    return f->commit();
}

Status check_output_path(const std::string& path) {
    auto f = AtomicFile::create(path);
    if (!f) return f.error();
    f->discard();
    return {};
}

}  // namespace spt
