// spt cat: joins .spt files (a farm's shots) without re-coding a stroke (spt/concat.hpp).
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "plan/plan_parts.hpp"
#include "spt/concat.hpp"

namespace spt::cli {

namespace fs = std::filesystem;

int cmd_cat(int argc, char** argv) {
    Args args("cat", "join .spt files losslessly: frames copied, a new index written",
              "spt cat A.spt B.spt ... -o OUT.spt [--quiet]");
    args.positional("PARTS", "the files to join, in order", true, true)
        .option("output", "OUT.spt", "the joined file (must not be one of the parts)", 'o')
        .flag("quiet", "print nothing but errors", 'q')
        .epilog("No stroke is decoded or re-coded: each frame chunk is copied with its frame number "
                "(and CRC) changed, then a new header, metadata, ROI list, index and end are written "
                "(format/SPEC.md 9.6). The parts must agree on the canvas, frame rate, colour "
                "encoding, background, stroke sets, orientations and templates, be complete and start "
                "with a key frame. Shot files of an `spt plan` must be given once each, in order, "
                "complete. Metadata entries the parts do not share are dropped (named on stderr).\n"
                "Exit 0 on success, 1 when a part cannot be joined (the message names it), 2 bad usage.");
    if (int rc = args.parse(argc, argv); rc >= 0) return rc;
    const std::vector<std::string> parts = args.pos_all("PARTS");
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
