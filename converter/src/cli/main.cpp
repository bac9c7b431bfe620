// spt: paint images and video as brush strokes, and read, write, render and convert .spt files.
#include <cstdio>
#include <cstring>
#include <string>

#include "cli/commands.hpp"
#include "spt/version.hpp"

namespace {

struct Command {
    const char* name;
    int (*run)(int, char**);
    const char* summary;
};

const Command kCommands[] = {
    {"paint", spt::cli::cmd_paint, "paint an image, an image sequence or a video into a .spt file"},
    {"render", spt::cli::cmd_render, "render a .spt file to images (PNG, EXR, TIFF), a sequence or a video"},
    {"info", spt::cli::cmd_info, "describe a .spt file: header, frames, strokes, bytes per section"},
    {"verify", spt::cli::cmd_verify, "check every checksum and decode every frame"},
    {"pack", spt::cli::cmd_pack, "re-code a .spt file: stored to range-coded, or back with --stored"},
    {"import", spt::cli::cmd_import, "bring strokes from other painters (JSON, SVG, geometrize) into .spt"},
    {"export", spt::cli::cmd_export, "write a .spt file as SVG (one per frame), a JSON stroke list or a web page"},
    {"plan", spt::cli::cmd_plan, "plan a farm job: a sequence or video cut into shots, each a task"},
    {"farm", spt::cli::cmd_farm, "paint a plan on a render farm (Slurm) and join it; or its status"},
    {"cat", spt::cli::cmd_cat, "join .spt files (a farm's shots) losslessly: frames copied, a new index"},
    {"compare", spt::cli::cmd_compare, "PSNR and SSIM of one image (or sequence) against another"},
};

void usage(FILE* f) {
    std::fprintf(f,
                 "spt %s: painterly animation as brush strokes (.spt format %d.%d)\n\n"
                 "usage: spt <command> [options]    (spt <command> --help for its options)\n\n"
                 "commands:\n",
                 spt::library_version(), SPT_FORMAT_MAJOR, SPT_FORMAT_MINOR);
    for (const auto& c : kCommands) std::fprintf(f, "  %-8s %s\n", c.name, c.summary);
    std::fprintf(f, "\n  --version  print the version and exit\n");
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        usage(stderr);
        return 2;
    }
    const std::string cmd = argv[1];
    if (cmd == "--help" || cmd == "-h" || cmd == "help") {
        usage(stdout);
        return 0;
    }
    if (cmd == "--version") {
        std::printf("spt %s (format %d.%d)\n", spt::library_version(), SPT_FORMAT_MAJOR, SPT_FORMAT_MINOR);
        return 0;
    }
    for (const auto& c : kCommands) {
        if (cmd == c.name) return c.run(argc - 1, argv + 1);
    }
    std::fprintf(stderr, "spt: unknown command '%s' (see 'spt --help')\n", cmd.c_str());
    return 2;
}
