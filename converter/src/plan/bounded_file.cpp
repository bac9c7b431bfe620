#include "plan/bounded_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace spt::plan {

json::ParseLimits plan_parse_limits() {
    json::ParseLimits lim;
    lim.max_bytes = kMaxPlanFileBytes;
    lim.max_values = kMaxPlanValues;
    return lim;
}

Result<std::string> read_bounded_file(const std::string& path, size_t max_bytes, const char* what) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return make_error(Code::IoError, path + ": cannot open the " + what + ": " + std::strerror(errno));
    struct Closer { int fd; ~Closer() { ::close(fd); } } closer{fd};
    struct stat st;
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode))
        return make_error(Code::InvalidArgument, path + ": the " + what + " is not a regular file");
    auto too_big = [&](uint64_t n) {
        return make_error(Code::LimitExceeded, path + ": the " + what + " is " + std::to_string(n) +
                                                   " bytes, over the limit of " + std::to_string(max_bytes >> 20) + " MiB");
    };
    if (uint64_t(st.st_size) > max_bytes) return too_big(uint64_t(st.st_size));
    // Read at most one byte past the cap: a file that grew since fstat is refused the same way.
    std::string text(size_t(st.st_size), '\0');
    size_t got = 0;
    for (;;) {
        if (got == text.size()) {
            if (text.size() > max_bytes) return too_big(text.size());
            text.resize(std::min(max_bytes + 1, text.size() + 65536));
        }
        const ssize_t n = ::read(fd, text.data() + got, text.size() - got);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return make_error(Code::IoError, path + ": cannot read the " + what + ": " + std::strerror(errno));
        if (n == 0) break;
        got += size_t(n);
    }
    text.resize(got);
    return text;
}

}  // namespace spt::plan
