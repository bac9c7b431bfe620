// spt farm: a plan's shots as tasks of a farm manager and their join (farm/README.md).
//   spt farm slurm PLAN.json -o OUT.spt [--partition P] [--wait] [--retries N] [-- sbatch options]
//   spt farm status PLAN.json [--json]
#include <chrono>
#include <climits>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <thread>

#include <unistd.h>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "farm/farm_job.hpp"
#include "spt_json/write.hpp"

namespace spt::cli {

namespace {

int fail(const std::string& msg) { return command_failed("farm", msg); }

std::string self_exe() {
    char buf[PATH_MAX];
    const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
    if (n <= 0) return "spt";
    buf[n] = 0;
    return buf;
}

// Follows a submission until the output is joined or something failed.
int wait_for(const std::string& plan, farm::Engine& engine) {
    std::string last;
    auto printed = std::chrono::steady_clock::now();
    for (;;) {
        Result<farm::FarmStatus> st = farm::farm_status(plan, &engine);
        if (!st) return fail(st.error().message);
        // A line when a shot changes state, else every 10 s (the rate and time left).
        const std::string key = std::to_string(st->count(farm::ShotState::Done)) + "/" +
                                std::to_string(st->count(farm::ShotState::Running)) + "/" +
                                std::to_string(st->count(farm::ShotState::Failed)) + "/" + std::to_string(st->joined);
        if (key != last || std::chrono::steady_clock::now() - printed > std::chrono::seconds(10)) {
            std::fprintf(stderr, "spt farm: %s\n", st->progress_line().c_str());
            last = key;
            printed = std::chrono::steady_clock::now();
        }
        if (st->count(farm::ShotState::Failed) > 0) {
            if (Status c = engine.cancel(st->ids); !c) std::fprintf(stderr, "spt farm: %s\n", c.error().message.c_str());
            for (size_t k = 0; k < st->shots.size(); ++k)
                if (st->shots[k] == farm::ShotState::Failed)
                    std::fprintf(stderr, "spt farm: shot %zu failed after %d attempts: see %s/logs/shot-%zu.log\n", k,
                                 st->attempts[k], st->state_dir.c_str(), k);
            return fail(plan + ": not joined; fix the cause and submit again (finished shots are kept)");
        }
        if (st->joined && !st->join_queued) {
            std::fprintf(stderr, "spt farm: %s: joined\n", st->output.c_str());
            return 0;
        }
        if (!st->join_queued) {
            // Markers are written before the job ends; look once more before calling it lost.
            std::this_thread::sleep_for(std::chrono::milliseconds(500));
            Result<farm::FarmStatus> again = farm::farm_status(plan, &engine);
            if (again && again->joined) continue;
            return fail("the join did not write " + st->output + " (see " + st->state_dir + "/logs/join.log)");
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(500));
    }
}

int farm_slurm(int argc, char** argv) {
    Args a("farm slurm", "paint a plan on a Slurm cluster: one job array task per shot, then the join",
           "spt farm slurm PLAN.json -o OUT.spt [--partition P] [--wait] [--retries N] [-- sbatch options]");
    a.positional("PLAN.json", "the plan (spt plan)")
        .positional("SBATCH", "options for sbatch, after --", false, true)
        .option("output", "OUT.spt", "the joined painting", 'o')
        .option("partition", "P", "the Slurm partition")
        .option("retries", "N", "attempts after the first for a failing shot", 0, "2")
        .flag("wait", "block until OUT.spt is written; report failures")
        .epilog("Submits one job array (array index = shot) and a join job that depends on it "
                "(afterok) and writes OUT.spt with spt cat. Shot files, logs and markers live in "
                "PLAN.farm/ beside the plan, on a file system the nodes share. Submitting the same "
                "plan again keeps every shot file that verifies and paints only the others. Prints "
                "the job ids. Exit 0 when submitted (with --wait: when joined), 1 on failure.");
    if (int rc = a.parse(argc, argv); rc >= 0) return rc;
    const std::string out = a.get("output");
    if (out.empty()) return a.usage_error("missing -o OUT.spt");
    long retries = 2;
    if (!a.get_long("retries", retries, 0, 100)) return 2;
    farm::SubmitOptions o;
    o.plan_path = a.pos("PLAN.json");
    o.output = out;
    o.partition = a.get("partition");
    o.extra = a.pos_all("SBATCH");
    o.retries = int(retries);
    o.spt = self_exe();
    std::unique_ptr<farm::Engine> engine = farm::make_slurm_engine();
    Result<farm::SubmitReport> rep = farm::submit_plan(*engine, o);
    if (!rep) return fail(rep.error().message);
    std::printf("tasks %s\njoin %s\n", rep->ids.tasks_id.empty() ? "-" : rep->ids.tasks_id.c_str(), rep->ids.join_id.c_str());
    std::fflush(stdout);
    std::fprintf(stderr, "spt farm: %zu shots to paint, %zu kept from before (verified); state in %s\n",
                 rep->painting.size(), rep->reused.size(), rep->state_dir.c_str());
    if (!a.has("wait")) return 0;
    return wait_for(o.plan_path, *engine);
}

int farm_status(int argc, char** argv) {
    Args a("farm status", "which shots of a submitted plan are done, running, pending or failed",
           "spt farm status PLAN.json [--json]");
    a.positional("PLAN.json", "the plan").flag("json", "one JSON document: {shots: [{index, state, attempts, frames}], done, running, pending, failed, frames_per_second, ...}");
    if (int rc = a.parse(argc, argv); rc >= 0) return rc;
    Result<farm::FarmStatus> st = farm::farm_status(a.pos("PLAN.json"));
    if (!st) return fail(st.error().message);
    if (a.has("json")) {
        json::Doc j = {{"plan", st->plan.id}, {"engine", st->ids.engine}, {"tasks_id", st->ids.tasks_id},
                       {"join_id", st->ids.join_id}, {"output", st->output}, {"joined", st->joined},
                       {"done", uint64_t(st->count(farm::ShotState::Done))}, {"running", uint64_t(st->count(farm::ShotState::Running))},
                       {"pending", uint64_t(st->count(farm::ShotState::Pending))}, {"failed", uint64_t(st->count(farm::ShotState::Failed))},
                       {"frames_painted", st->frames_painted}, {"frames_to_paint", st->frames_to_paint},
                       {"elapsed_seconds", json::number(st->elapsed)}, {"frames_per_second", json::number(st->frames_per_second())}};
        json::Doc& shots = j["shots"] = json::Doc::array();
        for (size_t k = 0; k < st->shots.size(); ++k)
            shots.push_back({{"index", uint64_t(k)}, {"state", farm::shot_state_name(st->shots[k])}, {"attempts", st->attempts[k]},
                             {"reused", bool(st->reused[k])}, {"frames", st->plan.shots[k].frames()}});
        std::printf("%s\n", json::dump(j, 2).c_str());
        return 0;
    }
    std::printf("plan %s on %s (tasks %s, join %s)\n", st->plan.id.c_str(), st->ids.engine.c_str(),
                st->ids.tasks_id.empty() ? "-" : st->ids.tasks_id.c_str(), st->ids.join_id.c_str());
    for (size_t k = 0; k < st->shots.size(); ++k)
        std::printf("shot %zu  frames %ld-%ld  %s%s  attempts %d\n", k, st->plan.shots[k].first, st->plan.shots[k].last,
                    farm::shot_state_name(st->shots[k]), st->reused[k] ? " (kept)" : "", st->attempts[k]);
    std::printf("%s\n", st->progress_line().c_str());
    return 0;
}

}  // namespace

int cmd_farm(int argc, char** argv) {
    const std::string sub = argc > 1 ? argv[1] : "";
    if (sub == "slurm") return farm_slurm(argc - 1, argv + 1);
    if (sub == "status") return farm_status(argc - 1, argv + 1);
    if (sub == "--help" || sub == "-h") {
        std::printf("usage: spt farm slurm PLAN.json -o OUT.spt [--partition P] [--wait] [-- sbatch options]\n"
                    "       spt farm status PLAN.json [--json]\n");
        return 0;
    }
    std::fprintf(stderr, "spt farm: expected 'slurm' or 'status', got '%s' (see spt farm --help)\n", sub.c_str());
    return 2;
}

}  // namespace spt::cli
