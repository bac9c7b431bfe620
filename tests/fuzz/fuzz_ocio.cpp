// Fuzz target: an OCIO config (the --ocio / $OCIO path: io/ocio_references.cpp's loop guard,
// then OpenColorIO through OpenImageIO, then io/color_config.cpp's look-ups and a processor
// each way between linear Rec.709 and sRGB, where a cyclic config used to overflow the stack).
// Any bytes in: a colour setup or an error out, never a crash or a hang.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <memory>
#include <string>

#include "io/color_config.hpp"
#include "io/ocio_references.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    // OCIO reads configs from files: one per process, rewritten for every input, removed at exit.
    struct Scratch {
        std::string path = "/tmp/spt-fuzz-ocio-" + std::to_string(::getpid()) + ".ocio";
        ~Scratch() { ::unlink(path.c_str()); }
    };
    static const Scratch scratch;
    const std::string& path = scratch.path;
    {
        std::ofstream f(path, std::ios::binary | std::ios::trunc);
        f.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    }
    if (!spt::io::check_ocio_references(path)) return 0;
    // color_config() caches by path; the same steps without the cache.
    spt::io::ColorSetup cs;
    auto c = std::make_shared<OIIO::ColorConfig>(path);
    if (c->has_error() || c->getNumColorSpaces() <= 0) {
        (void)c->geterror();
        (void)OIIO::geterror();
        return 0;
    }
    cs.config = std::move(c);
    cs.source = path;
    auto lin = spt::io::linear_rec709_space(cs);
    auto srgb = spt::io::srgb_space(cs);
    (void)spt::io::find_colorspace(cs, "ACEScg");
    (void)spt::io::known_colorspaces_text(cs);
    if (lin && srgb) {
        (void)spt::io::color_transform(cs, *lin, *srgb);
        (void)spt::io::color_transform(cs, *srgb, *lin);
    }
    (void)OIIO::geterror();
    return 0;
}
