#include "cli/paint_options.hpp"

#include <cstdio>
#include <cstring>

#include "cli/args.hpp"
#include "job/option_table.hpp"

namespace spt::cli {

namespace {

bool for_command(const job::OptionRow& r, bool plan) { return r.commands & (plan ? job::kForPlan : job::kForPaint); }

// The options of `spt paint` (or `spt plan`), declared from the option table: CLI11 parses them
// and writes --help from them.
void declare(Args& a, bool plan) {
    a.positional("IN", "an image, an image sequence (shot.####.exr, shot.%04d.png, shot.1-120#.png), a folder "
                       "of frames, or a video file")
        .option("output", "FILE", plan ? "the plan to write, JSON (required); its tasks paint with the options below"
                                       : "the .spt file to write (required)", 'o');
    std::string group;
    for (const job::OptionRow& r : job::option_rows()) {
        if (!for_command(r, plan)) continue;
        if (r.group != group) a.group(group = r.group);
        if (r.kind == job::OptionKind::Flag) a.flag(r.name, r.help);
        else if (r.kind == job::OptionKind::List) a.multi(r.name, r.metavar, r.help);
        else a.option(r.name, r.metavar, r.help, 0, r.def);
    }
    if (!plan) a.flag("options-json", "print the option table above as JSON (for front ends such as the Blender add-on) and exit");
    a.epilog(
            "Paints an image with brush strokes (the Stochastic Paintbrush Transformation): random\n"
            "candidate strokes, coarse to fine, each kept only if it brings the painting closer to\n"
            "the image. Writes the strokes to OUT.spt (written atomically: no half-written file).\n"
            "\n"
            "IN is any image OpenImageIO reads (PNG, JPEG, TIFF, EXR, ...), in the colour space that\n"
            "--colorspace names (default: sRGB for 8/16-bit files, scene-linear Rec.709 for float files),\n"
            "converted through OpenImageIO's colour management (OCIO: --ocio or $OCIO). The srgb8\n"
            "encoding paints in 8-bit sRGB (\"linear\" -> \"sRGB\", values above 1 clip); linear keeps\n"
            "scene-linear values. With --alpha on the canvas is transparent where IN is; otherwise alpha\n"
            "is composited over --background. NaN, infinite and negative input values are replaced\n"
            "(with a warning).\n"
            "\n"
            "For an image sequence or a video, OUT.spt holds key frames (the first frame, the first\n"
            "after each detected cut, and at least every --keyframe-interval frames) painted fully,\n"
            "and inter frames in which the strokes travel with the optical flow and only the areas\n"
            "that changed are repainted. Ctrl-C / SIGTERM stops after the current frame and leaves a\n"
            "valid OUT.spt holding every finished frame.\n"
            "\n"
            "exit status: 0 success, 1 failure (unreadable input, write error), 2 bad usage\n");
}

}  // namespace

int parse_paint_options(int argc, char** argv, PaintCommandOptions& o, const char* command) {
    const bool plan = std::string(command) == "plan";
    if (!plan)  // before IN and -o are asked for: a front end asks the table alone
        for (int i = 1; i < argc; ++i)
            if (std::strcmp(argv[i], "--options-json") == 0) {
                std::fputs(job::options_json().c_str(), stdout);
                return 0;
            }
    Args a(command, plan ? "plan a farm job: shots of a sequence or video, each a task" : "paint an image, an image sequence or a video into a .spt file",
           plan ? "spt plan IN -o PLAN.json [--max-task-frames N] [paint options]" : "spt paint IN -o OUT.spt [options]");
    declare(a, plan);
    if (int rc = a.parse(argc, argv); rc >= 0) return rc;
    o.input = a.pos("IN");
    o.output = a.get("output");
    std::vector<std::string> given;
    for (const job::OptionRow& r : job::option_rows()) {
        if (!for_command(r, plan) || !a.has(r.name)) continue;
        given.push_back(r.name);
        const std::vector<std::string> values = r.kind == job::OptionKind::Flag   ? std::vector<std::string>{"true"}
                                                : r.kind == job::OptionKind::List ? a.all(r.name)
                                                                                  : std::vector<std::string>{a.get(r.name)};
        for (const std::string& v : values)
            if (std::string e = job::apply_option(r, v, o); !e.empty()) return a.usage_error(e);
    }
    if (o.output.empty()) return a.usage_error("no output given (-o OUT.spt)");
    if (std::string e = job::finish_job(o, given); !e.empty()) return a.usage_error(e);
    return -1;
}

}  // namespace spt::cli
