#include "io/template_loader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <system_error>

#include <OpenImageIO/imageio.h>

namespace spt::io {

namespace fs = std::filesystem;

namespace {

constexpr uint32_t kMaxSide = 1024;
constexpr size_t kMaxTemplates = 255;

bool is_image_name(const fs::path& p) {
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    static const char* const kExts[] = {".png", ".tif", ".tiff", ".jpg", ".jpeg", ".bmp", ".pgm", ".exr", ".webp"};
    return std::any_of(std::begin(kExts), std::end(kExts), [&](const char* e) { return ext == e; });
}

Result<Template> load_one(const fs::path& path) {
    const std::string name = path.string();
    auto in = OIIO::ImageInput::open(name);
    if (!in) {
        std::string why = OIIO::geterror();
        return make_error(Code::IoError, "template " + name + ": cannot read (" + (why.empty() ? "unknown format" : why) + ")");
    }
    const OIIO::ImageSpec spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || uint32_t(spec.width) > kMaxSide || uint32_t(spec.height) > kMaxSide) {
        in->close();
        return make_error(Code::LimitExceeded, "template " + name + ": " + std::to_string(spec.width) + "x" +
                                                   std::to_string(spec.height) + " is outside 1x1..1024x1024");
    }
    const int nch = spec.nchannels;
    if (nch < 1) return make_error(Code::Corrupt, "template " + name + ": no channels");
    std::vector<uint8_t> px(size_t(spec.width) * spec.height * nch);
    // Read as 8-bit (OIIO scales 16-bit and float data); sizes were checked above.
    if (!in->read_image(0, 0, 0, nch, OIIO::TypeDesc::UINT8, px.data())) {
        std::string why = in->geterror();
        in->close();
        return make_error(Code::IoError, "template " + name + ": read failed (" + why + ")");
    }
    in->close();
    Template t;
    t.kind = TemplateKind::Bitmap;
    t.width = uint16_t(spec.width);
    t.height = uint16_t(spec.height);
    t.name = path.stem().string();
    t.pixels.resize(size_t(spec.width) * spec.height);
    bool any = false;
    for (size_t i = 0; i < t.pixels.size(); ++i) {
        const uint8_t* p = px.data() + i * nch;
        uint8_t v = p[0];
        if (nch >= 3) v = uint8_t(std::lround(0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]));
        t.pixels[i] = v;
        any |= v != 0;
    }
    if (!any) return make_error(Code::InvalidArgument, "template " + name + ": every sample is 0 (no coverage)");
    return t;
}

}  // namespace

Result<std::vector<Template>> load_templates(const std::string& dir) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        return make_error(Code::IoError, "templates folder " + dir + ": not a folder (or does not exist)");
    std::vector<fs::path> files;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        if (it->is_regular_file(ec) && is_image_name(it->path())) files.push_back(it->path());
    }
    if (ec) return make_error(Code::IoError, "templates folder " + dir + ": " + ec.message());
    if (files.empty())
        return make_error(Code::InvalidArgument, "templates folder " + dir + ": no image files (.png, .tif, .jpg, ...)");
    if (files.size() > kMaxTemplates)
        return make_error(Code::LimitExceeded, "templates folder " + dir + ": " + std::to_string(files.size()) +
                                                   " images, at most 255 templates fit in a file");
    std::sort(files.begin(), files.end());  // name order: the template ids are stable
    std::vector<Template> out;
    for (const auto& f : files) {
        auto t = load_one(f);
        if (!t) return t.error();
        out.push_back(std::move(t.value()));
    }
    return out;
}

}  // namespace spt::io
