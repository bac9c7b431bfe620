// .lottie files (dotLottie): a zip holding manifest.json and animations/<id>.json. Read with
// minizip (zlib's contrib unzip); sizes are checked against the caller's cap before, and while,
// inflating, so a zip bomb stops at the cap.
#include <minizip/unzip.h>

#include <memory>

#include "lottie/zip.hpp"
#include "spt_json/json.hpp"

namespace spt::import::lottie {

namespace {

struct Closer { void operator()(void* z) const { if (z) unzClose(z); } };

Result<std::string> read_entry(unzFile z, const std::string& zip, const std::string& name, size_t cap) {
    if (unzLocateFile(z, name.c_str(), 1) != UNZ_OK) return make_error(Code::InvalidArgument, zip + ": no " + name + " in the archive");
    unz_file_info64 info{};
    if (unzGetCurrentFileInfo64(z, &info, nullptr, 0, nullptr, 0, nullptr, 0) != UNZ_OK)
        return make_error(Code::Corrupt, zip + ": " + name + ": unreadable zip entry");
    if (info.uncompressed_size > cap)
        return make_error(Code::LimitExceeded, zip + ": " + name + " is " + std::to_string(info.uncompressed_size) +
                                                   " bytes, above the " + std::to_string(cap) + "-byte input limit");
    if (unzOpenCurrentFile(z) != UNZ_OK) return make_error(Code::Corrupt, zip + ": " + name + ": cannot open the zip entry");
    std::string out;
    char buf[65536];
    for (;;) {
        const int n = unzReadCurrentFile(z, buf, sizeof buf);
        if (n < 0) { unzCloseCurrentFile(z); return make_error(Code::Corrupt, zip + ": " + name + ": damaged zip data"); }
        if (n == 0) break;
        if (out.size() + size_t(n) > cap) {
            unzCloseCurrentFile(z);
            return make_error(Code::LimitExceeded, zip + ": " + name + " inflates past the " + std::to_string(cap) + "-byte input limit");
        }
        out.append(buf, size_t(n));
    }
    if (unzCloseCurrentFile(z) != UNZ_OK) return make_error(Code::Corrupt, zip + ": " + name + ": zip checksum mismatch");
    return out;
}

}  // namespace

Result<std::string> dotlottie_animation(const std::string& path, size_t cap) {
    std::unique_ptr<void, Closer> z(unzOpen64(path.c_str()));
    if (!z) return make_error(Code::Corrupt, path + ": not a readable zip (.lottie) file");
    // The manifest names the animations; the first is the one imported.
    std::string name;
    if (auto m = read_entry(z.get(), path, "manifest.json", size_t(1) << 20); m.ok()) {
        auto v = json::parse(*m, path + ":manifest.json");
        if (!v) return v.error();
        if (const json::Value* a = v->find("animations"); a && a->is_array() && !a->items.empty())
            if (const json::Value* id = a->items[0].find("id"); id && id->is_string()) name = "animations/" + id->text + ".json";
        if (name.find("..") != std::string::npos) return make_error(Code::InvalidArgument, path + ": manifest animation id is not a plain name");
    }
    if (name.empty()) {  // no manifest: the first animations/*.json
        if (unzGoToFirstFile(z.get()) == UNZ_OK) do {
                char fn[512];
                if (unzGetCurrentFileInfo64(z.get(), nullptr, fn, sizeof fn, nullptr, 0, nullptr, 0) != UNZ_OK) break;
                const std::string f = fn;
                if (f.rfind("animations/", 0) == 0 && f.size() > 5 && f.substr(f.size() - 5) == ".json") { name = f; break; }
            } while (unzGoToNextFile(z.get()) == UNZ_OK);
        if (name.empty()) return make_error(Code::InvalidArgument, path + ": no animation in the .lottie archive");
    }
    return read_entry(z.get(), path, name, cap);
}

}  // namespace spt::import::lottie
