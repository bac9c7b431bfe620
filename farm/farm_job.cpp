#include "farm/farm_job.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "farm/process.hpp"
#include "plan/bounded_file.hpp"
#include "plan/plan_parts.hpp"
#include "spt/atomic_file.hpp"
#include "spt_json/json.hpp"
#include "spt_json/write.hpp"

namespace spt::farm {

namespace fs = std::filesystem;

namespace {

double now_seconds() {
    return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

// run/shot-K.attempts holds one "attempt exit-code" line per attempt.
constexpr size_t kMaxAttemptsBytes = size_t(1) << 20;

std::string run_dir(const std::string& state) { return state + "/run"; }
std::string marker(const std::string& state, size_t shot, const char* what) {
    return run_dir(state) + "/shot-" + std::to_string(shot) + "." + what;
}

// Through spt::AtomicFile like every output: whole or absent, never through a symlink.
Status write_text(const std::string& path, const std::string& text) {
    return write_file_atomic(path, text.data(), text.size());
}

// The shell's `>` and `>>` follow a symlink planted at the name; the wrappers write every
// marker to a fresh file (mktemp: O_EXCL, a random name) and rename it over the name (mv -T:
// replaces a symlink, never writes through it or into a folder it points at).
const char* kPutMarker =
    "put() { local t; t=$(mktemp \"$1.XXXXXX\") && printf '%s' \"$2\" > \"$t\" && mv -fT -- \"$t\" \"$1\"; }\n";

// The task wrapper: paints one shot, retrying a failed attempt up to `retries` times; leaves
// run/shot-K.done or run/shot-K.failed, and one "attempt exit-code" line per attempt.
std::string task_script(const SubmitOptions& o, const std::string& state, const std::string& plan) {
    std::ostringstream s;
    s << "#!/bin/bash\n"
         "# spt farm task: paints shot $1 of the plan; written by spt farm, run by the farm's engine\n"
         "# (which may set SPT_FARM_THREADS to the CPUs it gave the task).\n"
      << kPutMarker <<
         "k=\"$1\"\n"
         "run=" << shell_quote(run_dir(state)) << "\n"
         // The number alone goes through printf: the path may hold a %.
         "out=" << shell_quote(state + "/shots/shot-") << "\"$(printf %05d \"$k\")\".spt\n"
         "rm -f \"$run/shot-$k.done\" \"$run/shot-$k.failed\"\n"
         "for attempt in $(seq 1 " << (o.retries + 1) << "); do\n"
         "  echo \"spt farm: shot $k attempt $attempt on $(hostname) at $(date -u +%FT%TZ)\"\n"
         "  " << shell_quote(o.spt) << " paint --plan " << shell_quote(plan)
      << " --shot \"$k\" -o \"$out\" --progress plain ${SPT_FARM_THREADS:+--threads \"$SPT_FARM_THREADS\"} &\n"
         "  pid=$!\n"
         "  put \"$run/shot-$k.pid\" \"$pid\n\"\n"
         "  wait \"$pid\"; rc=$?\n"
         "  rm -f \"$run/shot-$k.pid\"\n"
         // The earlier attempts' lines, unless a symlink stands there (it is replaced unread).
         "  a=\"$run/shot-$k.attempts\"; prev=$( { [ -L \"$a\" ] || cat -- \"$a\"; } 2>/dev/null )\n"
         "  put \"$a\" \"${prev:+$prev\n}$attempt $rc\n\"\n"
         "  if [ \"$rc\" = 0 ]; then put \"$run/shot-$k.done\" ''; exit 0; fi\n"
         "  echo \"spt farm: shot $k attempt $attempt failed (exit $rc)\" >&2\n"
         "done\n"
         "put \"$run/shot-$k.failed\" ''\n"
         "exit 1\n";
    return s.str();
}

std::string join_script(const SubmitOptions& o, const std::string& state, const std::string& output) {
    // The shots come from a list file (shots.list, written beside it): a command line naming
    // 40,000 of them passed the system's argument limit.
    std::vector<std::string> argv = {o.spt, "cat", "--list", state + "/shots.list", "-o", output};
    return "#!/bin/bash\n# spt farm join: every shot, in order, into the output.\nset -e\n" + std::string(kPutMarker) +
           shell_line(argv) + "\nput " + shell_quote(run_dir(state) + "/join.done") + " ''\n";
}

std::string job_json(const Submitted& ids, const std::string& output, double submitted,
                     const std::vector<size_t>& painting, const std::vector<size_t>& reused) {
    const json::Doc j = {{"engine", ids.engine}, {"tasks_id", ids.tasks_id}, {"join_id", ids.join_id}, {"output", output},
                         {"submitted_ms", uint64_t(submitted * 1000.0)},  // unix time; whole ms keep the JSON number exact
                         {"painting", painting}, {"reused", reused}};
    return json::dump(j, 2) + "\n";
}

}  // namespace

std::string state_dir_for(const std::string& plan_path) {
    std::error_code ec;
    fs::path p = fs::absolute(plan_path, ec).lexically_normal();
    if (p.extension() == ".json") p.replace_extension();
    return p.string() + ".farm";
}

std::string shot_file(const std::string& state_dir, size_t shot) {
    char name[40];
    std::snprintf(name, sizeof name, "/shots/shot-%05zu.spt", shot);
    return state_dir + name;
}

const char* shot_state_name(ShotState s) {
    switch (s) {
        case ShotState::Done: return "done";
        case ShotState::Running: return "running";
        case ShotState::Pending: return "pending";
        case ShotState::Failed: return "failed";
        case ShotState::Lost: return "not queued";
    }
    return "?";
}

Result<SubmitReport> submit_plan(Engine& engine, const SubmitOptions& o) {
    Result<plan::Plan> p = plan::read_plan(o.plan_path);
    if (!p) return p.error();
    SubmitReport rep;
    const std::string state = rep.state_dir = state_dir_for(o.plan_path);
    std::error_code ec;
    const std::string plan_abs = fs::absolute(o.plan_path, ec).lexically_normal().string();
    const std::string output = fs::absolute(o.output, ec).lexically_normal().string();
    // A submission still on the farm is not submitted twice.
    if (fs::exists(state + "/job.json")) {
        Result<FarmStatus> st = farm_status(o.plan_path, &engine);
        if (st && (st->join_queued || st->count(ShotState::Running) || st->count(ShotState::Pending)))
            return make_error(Code::BadState, o.plan_path + ": already on the farm (" + st->ids.engine + " jobs " +
                                                  st->ids.tasks_id + " " + st->ids.join_id + "); see spt farm status");
    }
    // Files are written into these folders by name: a symlink in their place would send them
    // elsewhere.
    for (const char* d : {"", "/shots", "/logs", "/run"}) {
        if (fs::is_symlink(state + d, ec))
            return make_error(Code::BadState, state + d + ": is a symlink; spt farm writes only into folders of its own");
        fs::create_directories(state + d, ec);
        if (ec) return make_error(Code::IoError, state + d + ": cannot create: " + ec.message());
    }
    fs::remove(run_dir(state) + "/join.done", ec);
    // Shots already painted and sound are kept; anything else of a shot is cleared.
    for (size_t k = 0; k < p->shots.size(); ++k) {
        const std::string f = shot_file(state, k);
        if (fs::exists(f) && plan::verify_shot(*p, k, f)) {
            rep.reused.push_back(k);
            if (Status st = write_text(marker(state, k, "done"), ""); !st) return st.error();
            fs::remove(marker(state, k, "failed"), ec);
            continue;
        }
        for (const char* m : {"done", "failed", "attempts", "pid"}) fs::remove(marker(state, k, m), ec);
        fs::remove(f, ec);
        fs::remove(f + ".partial", ec);
        rep.painting.push_back(k);
    }
    const std::string task = state + "/task.sh", join = state + "/join.sh";
    if (Status st = write_text(task, task_script(o, state, plan_abs)); !st) return st.error();
    if (Status st = write_text(join, join_script(o, state, output)); !st) return st.error();
    std::string list;
    for (size_t k = 0; k < p->shots.size(); ++k) list += shot_file(state, k) + "\n";
    if (Status st = write_text(state + "/shots.list", list); !st) return st.error();
    FarmJob job;
    job.name = "spt-" + p->id.substr(0, 8);
    job.state_dir = state;
    for (size_t k : rep.painting) {
        Task t;
        t.shot = k;
        t.command = {"/bin/bash", task, std::to_string(k)};
        char log[40];
        std::snprintf(log, sizeof log, "/logs/shot-%zu.log", k);
        t.log = state + log;
        // The engine's own writer opens the log by name: a symlink there is removed first.
        if (fs::is_symlink(t.log, ec)) fs::remove(t.log, ec);
        job.tasks.push_back(std::move(t));
    }
    job.join = {"/bin/bash", join};
    job.join_log = state + "/logs/join.log";
    if (fs::is_symlink(job.join_log, ec)) fs::remove(job.join_log, ec);
    job.retries = o.retries;
    job.partition = o.partition;
    job.extra = o.extra;
    const double submitted = now_seconds();
    Result<Submitted> ids = engine.submit(job);
    if (!ids) return ids.error();
    rep.ids = *ids;
    if (Status st = write_text(state + "/job.json", job_json(rep.ids, output, submitted, rep.painting, rep.reused)); !st)
        return st.error();
    return rep;
}

size_t FarmStatus::count(ShotState s) const {
    size_t n = 0;
    for (ShotState x : shots) n += x == s;
    return n;
}

std::string FarmStatus::progress_line() const {
    char buf[320];
    const double fps = frames_per_second();
    const uint64_t left = frames_to_paint > frames_painted ? frames_to_paint - frames_painted : 0;
    std::string eta = "unknown";
    if (left == 0) eta = "0 s";
    else if (fps > 0) {
        const double s = double(left) / fps;
        char e[32];
        if (s < 120) std::snprintf(e, sizeof e, "%.0f s", s);
        else if (s < 7200) std::snprintf(e, sizeof e, "%.0f min", s / 60);
        else std::snprintf(e, sizeof e, "%.1f h", s / 3600);
        eta = e;
    }
    std::snprintf(buf, sizeof buf,
                  "shots %zu/%zu done (%zu reused), %zu running, %zu pending, %zu failed; %llu/%llu frames painted, "
                  "%.2f frames/s over the farm, about %s left%s",
                  count(ShotState::Done), shots.size(), size_t(std::count(reused.begin(), reused.end(), true)),
                  count(ShotState::Running), count(ShotState::Pending), count(ShotState::Failed),
                  (unsigned long long)frames_painted, (unsigned long long)frames_to_paint, fps, eta.c_str(),
                  joined ? "; joined" : join_queued ? "" : "; join not queued");
    return buf;
}

Result<FarmStatus> farm_status(const std::string& plan_path, Engine* engine) {
    Result<plan::Plan> p = plan::read_plan(plan_path);
    if (!p) return p.error();
    FarmStatus st;
    st.plan = std::move(*p);
    st.state_dir = state_dir_for(plan_path);
    const std::string job_path = st.state_dir + "/job.json";
    if (!fs::exists(job_path)) return make_error(Code::BadState, plan_path + ": not submitted to a farm (no " + job_path + ")");
    Result<std::string> job_text = plan::read_bounded_file(job_path, plan::kMaxPlanFileBytes, "farm state file");
    if (!job_text) return job_text.error();
    Result<json::Value> doc = json::parse(*job_text, job_path, plan::plan_parse_limits());
    if (!doc) return doc.error();
    auto text = [&](const char* k) {
        const json::Value* v = doc->find(k);
        return v && v->is_string() ? v->text : std::string();
    };
    st.ids.engine = text("engine");
    st.ids.state_dir = st.state_dir;
    st.ids.tasks_id = text("tasks_id");
    st.ids.join_id = text("join_id");
    st.output = text("output");
    const json::Value* sub = doc->find("submitted_ms");
    st.elapsed = sub && sub->is_number() ? now_seconds() - std::strtod(sub->text.c_str(), nullptr) / 1000.0 : 0;
    const size_t n = st.plan.shots.size();
    st.reused.assign(n, false);
    if (const json::Value* r = doc->find("reused"); r && r->is_array())
        for (const auto& v : r->items)
            if (v.is_number() && size_t(v.number) < n) st.reused[size_t(v.number)] = true;
    std::vector<bool> painting(n, false);
    if (const json::Value* r = doc->find("painting"); r && r->is_array())
        for (const auto& v : r->items)
            if (v.is_number() && size_t(v.number) < n) painting[size_t(v.number)] = true;

    std::unique_ptr<Engine> own;
    if (!engine) {
        if (st.ids.engine != "slurm") return make_error(Code::Unsupported, job_path + ": unknown engine '" + st.ids.engine + "'");
        own = make_slurm_engine();
        engine = own.get();
    }
    Result<std::map<size_t, QueueState>> queued = engine->queued_tasks(st.ids);
    if (!queued) return queued.error();
    Result<bool> jq = engine->join_queued(st.ids);
    if (!jq) return jq.error();
    st.join_queued = *jq;
    std::error_code ec;
    st.joined = fs::exists(run_dir(st.state_dir) + "/join.done", ec) && fs::exists(st.output, ec);
    st.shots.assign(n, ShotState::Lost);
    st.attempts.assign(n, 0);
    for (size_t k = 0; k < n; ++k) {
        // One short line per attempt: a marker grown past the cap is an error, not read.
        if (const std::string am = marker(st.state_dir, k, "attempts"); fs::exists(am, ec)) {
            Result<std::string> a = plan::read_bounded_file(am, kMaxAttemptsBytes, "farm state file");
            if (!a) return a.error();
            std::istringstream in(*a);
            for (std::string line; std::getline(in, line);) st.attempts[k] += !line.empty();
        }
        const auto q = queued->find(k);
        if (fs::exists(marker(st.state_dir, k, "done"), ec) && fs::exists(shot_file(st.state_dir, k), ec))
            st.shots[k] = ShotState::Done;
        else if (fs::exists(marker(st.state_dir, k, "failed"), ec)) st.shots[k] = ShotState::Failed;
        else if (q != queued->end()) st.shots[k] = q->second == QueueState::Running ? ShotState::Running : ShotState::Pending;
        else if (fs::exists(marker(st.state_dir, k, "pid"), ec)) st.shots[k] = ShotState::Running;
        if (painting[k]) {
            st.frames_to_paint += st.plan.shots[k].frames();
            if (st.shots[k] == ShotState::Done) st.frames_painted += st.plan.shots[k].frames();
        }
    }
    return st;
}

}  // namespace spt::farm
