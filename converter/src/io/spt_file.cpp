// Shared .spt helpers for the commands (see spt_file.hpp).
#include "io/spt_file.hpp"

#include <filesystem>
#include <system_error>

namespace spt::io {

std::string describe_error(const std::string& path, const Error& e) {
    std::string m = e.message;
    if (m.rfind(path, 0) != 0) m = path + ": " + m;
    if (e.offset != 0 && m.find(std::to_string(e.offset)) == std::string::npos)
        m += " (byte offset " + std::to_string(e.offset) + ")";
    return m;
}

Result<std::unique_ptr<Reader>> open_spt(const std::string& path, const ReaderOptions& opts) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return make_error(Code::IoError, path + ": no such file");
    if (std::filesystem::is_directory(path, ec))
        return make_error(Code::IoError, path + ": is a folder, not a .spt file");
    auto r = Reader::open(path, opts);
    if (!r) {
        Error e = r.error();
        e.message = describe_error(path, e);
        return e;
    }
    return r;
}

std::string frame_place(const Reader& r, size_t pos) {
    const auto& f = r.frames();
    if (pos >= f.size()) return "frame position " + std::to_string(pos);
    return "frame " + std::to_string(f[pos].index) + " (byte offset " + std::to_string(f[pos].offset) + ")";
}

std::string frame_error(const Reader& r, size_t pos, const std::string& path, const Error& e) {
    const std::string d = describe_error(path, e);
    if (d.find("frame") != std::string::npos) return d;
    return path + ": " + frame_place(r, pos) + ": " + d.substr(d.rfind(path, 0) == 0 ? path.size() + 2 : 0);
}

}  // namespace spt::io
