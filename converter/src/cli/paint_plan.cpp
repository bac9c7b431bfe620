#include "cli/paint_plan.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/plan_job.hpp"
#include "plan/plan_parts.hpp"
#include "spt/atomic_file.hpp"
#include "spt/concat.hpp"
#include "spt/version.hpp"

namespace spt::cli {

namespace fs = std::filesystem;

namespace {

int fail(const std::string& msg) { return command_failed("paint", msg); }

// What is at a path (not following a symlink): a failed shot removes its output only when the
// file there is not what was there before it ran, i.e. this run linked it into place.
struct PathIdentity {
    bool exists = false;
    dev_t dev = 0;
    ino_t ino = 0;
    static PathIdentity of(const std::string& path) {
        struct stat st;
        if (::lstat(path.c_str(), &st) != 0) return {};
        return {true, st.st_dev, st.st_ino};
    }
    bool same(const PathIdentity& o) const { return exists == o.exists && dev == o.dev && ino == o.ino; }
};

// Removes `path` if it is a regular file this run created (not there, or another file, before).
void remove_if_created(const std::string& path, const PathIdentity& before) {
    struct stat st;
    if (::lstat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return;
    if (PathIdentity{true, st.st_dev, st.st_ino}.same(before)) return;
    std::error_code ec;
    fs::remove(path, ec);
}

}  // namespace

int paint_shot(const plan::Plan& p, const std::string& plan_path, size_t k, const std::string& output, int threads,
               io::ProgressMode mode) {
    const plan::Shot& s = p.shots.at(k);
    // The shot's job: the plan's options, its frames and its seed.
    PaintCommandOptions o;
    if (std::string e = apply_plan_job(p, plan_path, o); !e.empty()) return fail(e);
    o.input = p.input;
    o.output = output;
    o.fps = p.fps;
    o.frames = std::to_string(s.first) + "-" + std::to_string(s.last);
    o.paint.seed = s.seed;
    o.progress = mode;
    if (threads > 0) o.paint.threads = threads;
    // An interrupted or short shot keeps its finished frames in a valid file; a farm must not
    // take it for a painted shot.
    const PathIdentity before = PathIdentity::of(output);
    auto settle = [&](int rc, bool interrupted, uint64_t frames) {
        if (rc == 0 && !interrupted && frames == s.frames()) return 0;
        remove_if_created(output, before);
        return rc != 0 ? rc : fail(output + ": shot " + std::to_string(k) + " painted " + std::to_string(frames) +
                                       " of its " + std::to_string(s.frames()) + " frames");
    };
    std::vector<std::pair<std::string, std::string>> meta = {{"painter.seed", std::to_string(p.seed)}};
    for (auto& e : plan::shot_metadata(p.id, k, p.shots.size(), s.first, s.last)) meta.push_back(std::move(e));
    // A whole clip's budget: the shot's share.
    auto share = [&](uint64_t bytes) {
        return std::max<uint64_t>(64, uint64_t(std::llround(double(bytes) * double(s.frames()) / double(p.frames()))));
    };
    if (o.target_bytes > 0 && !o.target_bytes_per_second) o.target_bytes = share(o.target_bytes);
    ShotRun run;
    run.metadata = std::move(meta);
    // The plan placed the cuts and a shot has none inside, unless the plan left them to its
    // tasks: then the painter's detector runs on the shot's frames alone, from a fresh state.
    run.detect_cuts = p.cut_scan == "tasks";
    run.label = "paint shot " + std::to_string(k);
    const int rc = run_paint(o, &run);
    return settle(rc, run.interrupted, run.frames);
}

int paint_plan(int argc, char** argv) {
    Args a("paint", "paint the shots of a farm plan (spt plan)",
           "spt paint --plan PLAN.json [--shot K] -o OUT.spt [--threads N] [--progress MODE]");
    a.option("plan", "PLAN.json", "the plan (written by spt plan)")
        .option("shot", "K", "paint only shot K (a farm task; 0-based); default: every shot, joined")
        .option("output", "OUT.spt", "the shot file, or the whole painting", 'o')
        .option("threads", "N", "worker threads (default: all cores); the bytes do not depend on it")
        .option("progress", "MODE", io::kProgressHelp, 0, "auto")
        .epilog("Every painting option comes from the plan. Shots painted apart (on any machines, "
                "with any --threads) and joined with 'spt cat' in order give exactly the bytes of "
                "the painting without --shot.");
    if (int rc = a.parse(argc, argv); rc >= 0) return rc;
    const std::string out = a.get("output");
    if (out.empty()) return a.usage_error("missing -o OUT.spt");
    io::ProgressMode mode;
    if (!a.get_progress(mode)) return 2;
    long threads = 0, shot = -1;
    if (!a.get_long("threads", threads, 1, 1024) || !a.get_long("shot", shot, 0, 100000000)) return 2;
    Result<plan::Plan> p = plan::read_plan(a.get("plan"));
    if (!p) return fail(p.error().message);
    if (p->spt_version != library_version())
        return fail(a.get("plan") + ": written by spt " + p->spt_version + "; this is spt " + library_version() +
                    ", whose painter may paint other bytes: plan again with this spt");
    if (shot >= 0) {
        if (size_t(shot) >= p->shots.size())
            return a.usage_error("--shot " + std::to_string(shot) + ": the plan has shots 0-" + std::to_string(p->shots.size() - 1));
        return paint_shot(*p, a.get("plan"), size_t(shot), out, int(threads), mode);
    }
    // Every shot in this process, then the join: the farm's result on one machine. The shots go to
    // a fresh folder beside the output (mkdtemp: a name nobody else chose, so no folder or
    // symlink of the user's is touched); a killed process leaves it, ".NAME.shots-XXXXXX".
    if (Status c = spt::check_output_path(out); !c) return fail(c.error().message);
    const fs::path target(out);
    std::string templ = (target.parent_path() / ("." + target.filename().string() + ".shots-XXXXXX")).string();
    if (!::mkdtemp(templ.data())) return fail(templ + ": cannot create a folder for the shots: " + std::strerror(errno));
    const fs::path dir = templ;
    std::error_code ec;
    std::vector<std::string> parts;
    for (size_t k = 0; k < p->shots.size(); ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "shot-%05zu.spt", k);
        parts.push_back((dir / name).string());
        if (int rc = paint_shot(*p, a.get("plan"), k, parts.back(), int(threads), mode); rc != 0) {
            fs::remove_all(dir, ec);
            return rc;
        }
    }
    Result<ConcatReport> rep = concatenate(parts, out, plan::join_options(parts.size()));
    fs::remove_all(dir, ec);
    if (!rep) return fail(rep.error().message);
    for (const std::string& w : rep->warnings) std::fprintf(stderr, "spt paint: warning: %s\n", w.c_str());
    if (mode != io::ProgressMode::Json && mode != io::ProgressMode::None)
        std::fprintf(stderr, "spt paint: %s: %zu shots, %llu frames, %llu bytes\n", out.c_str(), parts.size(),
                     (unsigned long long)rep->frames, (unsigned long long)rep->bytes);
    return 0;
}

}  // namespace spt::cli
