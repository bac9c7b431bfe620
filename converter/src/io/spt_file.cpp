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

Status check_frames(Reader& r, const std::string& path, const std::vector<size_t>& positions, bool lost_matter,
                    std::vector<std::string>& warnings) {
    const auto& frames = r.frames();
    const Header& h = r.info().header;
    // Where the reader stopped, when it did: its last warning.
    const Error* stop = r.warnings().empty() ? nullptr : &r.warnings().back();
    std::string why = stop ? describe_error(path, *stop) : std::string("the file ends early");
    if (why.rfind(path + ": ", 0) == 0) why.erase(0, path.size() + 2);
    if (frames.empty())
        return make_error(Code::Corrupt, path + ": the file holds no decodable frame" + (stop ? ": " + why : std::string()));
    // As spt render counts them: frames short of the header's count, or of an unknown count.
    const bool lost = !r.complete() && (h.frame_count == kUnknownFrameCount || h.frame_count > frames.size());
    if (lost && lost_matter) {
        const uint64_t at = stop && stop->offset ? stop->offset : r.file_size();
        const std::string of = h.frame_count == kUnknownFrameCount ? "" : " of " + std::to_string(h.frame_count);
        return make_error(Code::Corrupt, path + ": frame " + std::to_string(frames.size()) + " (byte offset " +
                                             std::to_string(at) + ") cannot be read: " + why + "; the file holds " +
                                             std::to_string(frames.size()) + of + " frames");
    }
    if (auto rc = Renderer::create(h, r.info().templates); !rc)
        return make_error(rc.error().code, path + ": header/templates cannot be rendered: " + rc.error().message);
    for (size_t pos : positions)
        if (auto live = r.strokes_at(pos); !live)
            return make_error(live.error().code, frame_error(r, pos, path, live.error()), live.error().offset);
    if (!r.complete())
        for (const auto& w : r.warnings()) warnings.push_back(describe_error(path, w));
    return {};
}

}  // namespace spt::io
