// spt cat: joins .spt files (a farm's shots) without re-coding a stroke (spt/concat.hpp).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>
#include <system_error>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "plan/plan_parts.hpp"
#include "spt/concat.hpp"

namespace spt::cli {

namespace fs = std::filesystem;

namespace {

// A plan has at most 2^20 shots of paths far shorter than 4 KiB: the cap is checked before
// anything is read.
constexpr uintmax_t kMaxListBytes = uintmax_t(1) << 32;

Result<std::vector<std::string>> read_part_list(const std::string& path) {
    std::error_code ec;
    const uintmax_t size = fs::file_size(path, ec);
    if (ec) return make_error(Code::IoError, "--list " + path + ": " + ec.message());
    if (size > kMaxListBytes)
        return make_error(Code::LimitExceeded, "--list " + path + ": " + std::to_string(size) + " bytes, over the " +
                                                   std::to_string(kMaxListBytes) + " a list may have");
    std::ifstream in(path);
    if (!in) return make_error(Code::IoError, "--list " + path + ": cannot be read");
    std::vector<std::string> parts;
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) parts.push_back(line);
    return parts;
}

}  // namespace

int cmd_cat(int argc, char** argv) {
    Args args("cat", "join .spt files losslessly: frames copied, a new index written",
              "spt cat A.spt B.spt ... -o OUT.spt [--list FILE] [--quiet]");
    args.positional("PARTS", "the files to join, in order", false, true)
        .option("output", "OUT.spt", "the joined file (must not be one of the parts)", 'o')
        .option("list", "FILE", "more parts, one path a line, after those given as arguments (a farm's "
                                "join of more shots than a command line holds)")
        .flag("quiet", "print nothing but errors", 'q')
        .epilog("No stroke is decoded or re-coded: each frame chunk is copied with its frame number "
                "(and CRC) changed, then a new header, metadata, ROI list, index and end are written "
                "(format/SPEC.md 9.6). The parts must agree on the canvas, frame rate, colour "
                "encoding, background, stroke sets, orientations and templates, be complete and start "
                "with a key frame. Shot files of an `spt plan` must be given once each, in order, "
                "complete. Metadata entries the parts do not share are dropped (named on stderr).\n"
                "Exit 0 on success, 1 when a part cannot be joined (the message names it), 2 bad usage.");
    if (int rc = args.parse(argc, argv); rc >= 0) return rc;
    std::vector<std::string> parts = args.pos_all("PARTS");
    if (args.has("list")) {
        auto listed = read_part_list(args.get("list"));
        if (!listed) {
            std::fprintf(stderr, "spt cat: %s\n", listed.error().message.c_str());
            return 1;
        }
        parts.insert(parts.end(), listed->begin(), listed->end());
    }
    if (parts.empty()) return args.usage_error("no parts to join (give them, or --list FILE)");
    const std::string out = args.get("output");
    if (out.empty()) return args.usage_error("missing -o OUT.spt");
    std::error_code ec;
    for (const std::string& p : parts) {
        if (p == out || (fs::exists(out, ec) && fs::equivalent(p, out, ec)))
            return args.usage_error("-o " + out + " is also a part");
        if (!fs::is_regular_file(p, ec)) {  // before libspt, in plain words
            std::fprintf(stderr, "spt cat: %s: %s\n", p.c_str(), fs::exists(p, ec) ? "is not a file" : "no such file");
            return 1;
        }
    }

    const ConcatOptions co = plan::join_options(parts.size());
    Result<ConcatReport> rep = concatenate(parts, out, co);
    if (!rep) {
        std::fprintf(stderr, "spt cat: %s\n", rep.error().message.c_str());
        return 1;
    }
    for (const std::string& w : rep->warnings) std::fprintf(stderr, "spt cat: warning: %s\n", w.c_str());
    if (!args.has("quiet"))
        std::printf("%s: %llu parts, %llu frames, %llu bytes\n", out.c_str(), (unsigned long long)rep->parts,
                    (unsigned long long)rep->frames, (unsigned long long)rep->bytes);
    return 0;
}

}  // namespace spt::cli
