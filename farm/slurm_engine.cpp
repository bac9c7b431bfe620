// Slurm: the tasks are one job array (array index = shot), the join one batch job with
// --dependency=afterok on the array and --kill-on-invalid-dep=yes (a shot that finally failed
// cancels it instead of leaving it pending forever). --requeue lets Slurm run a task again
// after a node failure; failures of the task itself are retried by the task's wrapper
// (farm_job.cpp) inside its allocation, because a job requeued with `scontrol requeue` waits
// behind a BeginTime delay (measured here: still pending after 15 s).
#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "farm/engine.hpp"
#include "farm/process.hpp"
#include "spt/atomic_file.hpp"

namespace spt::farm {

namespace {

std::string trim(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ' || s.back() == '\r')) s.pop_back();
    // --parsable prints "id" or "id;cluster".
    const size_t semi = s.find(';');
    return semi == std::string::npos ? s : s.substr(0, semi);
}

Status write_text(const std::string& path, const std::string& text) {
    return write_file_atomic(path, text.data(), text.size());
}

// The shots as Slurm's array list, runs of consecutive numbers as ranges ("0-39999,40002"):
// a list of every number passed the 128 KiB argument limit at 40,000 shots.
std::string array_list(std::vector<uint64_t> shots) {
    std::sort(shots.begin(), shots.end());
    shots.erase(std::unique(shots.begin(), shots.end()), shots.end());
    std::string list;
    for (size_t i = 0; i < shots.size();) {
        size_t j = i;
        while (j + 1 < shots.size() && shots[j + 1] == shots[j] + 1) ++j;
        list += (list.empty() ? "" : ",") + std::to_string(shots[i]);
        if (j > i) list += "-" + std::to_string(shots[j]);
        i = j + 1;
    }
    return list;
}

// The cluster's MaxArraySize (array indices must be below it), or 0 when scontrol cannot say.
// Runs a Slurm client; its stderr goes to the state folder's logs/ (process.hpp).
Result<std::string> run(const std::vector<std::string>& argv, const std::string& state_dir) {
    if (state_dir.empty()) return make_error(Code::InvalidArgument, argv.at(0) + ": no state folder for its stderr");
    return run_capture(argv, stderr_file_for(state_dir, argv.at(0)));
}

uint64_t max_array_size(const std::string& state_dir) {
    Result<std::string> out = run({"scontrol", "show", "config"}, state_dir);
    if (!out) return 0;
    std::istringstream in(*out);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("MaxArraySize", 0) != 0) continue;
        const size_t eq = line.find('=');
        if (eq == std::string::npos) return 0;
        return std::strtoull(line.c_str() + eq + 1, nullptr, 10);
    }
    return 0;
}

class SlurmEngine final : public Engine {
public:
    std::string name() const override { return "slurm"; }

    Result<Submitted> submit(const FarmJob& job) override {
        Submitted ids;
        ids.engine = name();
        ids.state_dir = job.state_dir;
        std::vector<std::string> common;
        if (!job.partition.empty()) common.push_back("--partition=" + job.partition);
        if (!job.tasks.empty()) {
            // One script for the array: task i runs the command of shot i.
            // Written like every file of the state folder: whole, and never through a symlink.
            const std::string script = job.state_dir + "/slurm_tasks.sh";
            std::ostringstream s;
            s << "#!/bin/bash\n# spt farm: one shot per array task (array index = shot)\n"
                 "export SPT_FARM_THREADS=\"${SLURM_CPUS_PER_TASK:-}\"  # --cpus-per-task, when given\n"
                 "case \"$SLURM_ARRAY_TASK_ID\" in\n";
            std::vector<uint64_t> shots;
            for (const Task& t : job.tasks) {
                s << "  " << t.shot << ") exec " << shell_line(t.command) << " ;;\n";
                shots.push_back(t.shot);
            }
            const uint64_t last = *std::max_element(shots.begin(), shots.end());
            if (const uint64_t limit = max_array_size(job.state_dir); limit > 0 && last >= limit)
                return make_error(Code::InvalidArgument,
                                  "the plan's shot " + std::to_string(last) + " needs a Slurm array index below this " +
                                      "cluster's MaxArraySize (" + std::to_string(limit) + "): raise MaxArraySize in " +
                                      "slurm.conf, or plan fewer, longer shots (spt plan --max-task-frames)");
            const std::string list = array_list(shots);
            s << "esac\necho \"spt farm: no shot $SLURM_ARRAY_TASK_ID in this job\" >&2\nexit 2\n";
            if (Status st = write_text(script, s.str()); !st) return st.error();
            std::vector<std::string> argv = {"sbatch", "--parsable", "--job-name=" + job.name, "--array=" + list,
                                             "--requeue", "--ntasks=1", "--output=" + job.state_dir + "/logs/shot-%a.log"};
            argv.insert(argv.end(), common.begin(), common.end());
            argv.insert(argv.end(), job.extra.begin(), job.extra.end());
            argv.push_back(script);
            Result<std::string> out = run(argv, ids.state_dir);
            if (!out) return out.error();
            ids.tasks_id = trim(*out);
        }
        const std::string join_script = job.state_dir + "/slurm_join.sh";
        if (Status st = write_text(join_script, "#!/bin/bash\n# spt farm: the join, after every shot\nexec " +
                                                    shell_line(job.join) + "\n");
            !st)
            return st.error();
        std::vector<std::string> argv = {"sbatch", "--parsable", "--job-name=" + job.name + "-join", "--ntasks=1",
                                         "--output=" + job.join_log};
        if (!ids.tasks_id.empty())
            argv.insert(argv.end(), {"--dependency=afterok:" + ids.tasks_id, "--kill-on-invalid-dep=yes"});
        argv.insert(argv.end(), common.begin(), common.end());
        argv.insert(argv.end(), job.extra.begin(), job.extra.end());
        argv.push_back(join_script);
        Result<std::string> out = run(argv, ids.state_dir);
        if (!out) {
            // Best effort: the join failed to submit, and the tasks it would join are cancelled.
            if (!ids.tasks_id.empty()) (void)run({"scancel", ids.tasks_id}, ids.state_dir);
            return out.error();
        }
        ids.join_id = trim(*out);
        return ids;
    }

    Result<std::map<size_t, QueueState>> queued_tasks(const Submitted& ids) override {
        std::map<size_t, QueueState> m;
        if (ids.tasks_id.empty()) return m;
        // %K: array index; %t: compact state. A job id Slurm has forgotten is not an error.
        Result<std::string> out = run({"squeue", "--noheader", "--array", "--jobs=" + ids.tasks_id, "--format=%K %t"}, ids.state_dir);
        if (!out) {
            if (out.error().message.find("Invalid job id") != std::string::npos) return m;
            return out.error();
        }
        std::istringstream in(*out);
        std::string idx, st;
        while (in >> idx >> st) {
            char* end = nullptr;
            const unsigned long k = std::strtoul(idx.c_str(), &end, 10);
            if (*end) continue;  // a pending range "[3-5]" is listed per task with --array
            m[size_t(k)] = (st == "R" || st == "CG") ? QueueState::Running : QueueState::Pending;
        }
        return m;
    }

    Result<bool> join_queued(const Submitted& ids) override {
        if (ids.join_id.empty()) return false;
        Result<std::string> out = run({"squeue", "--noheader", "--jobs=" + ids.join_id, "--format=%t"}, ids.state_dir);
        if (!out) {
            if (out.error().message.find("Invalid job id") != std::string::npos) return false;
            return out.error();
        }
        return out->find_first_not_of(" \n") != std::string::npos;
    }

    Status cancel(const Submitted& ids) override {
        std::vector<std::string> argv = {"scancel"};
        if (!ids.tasks_id.empty()) argv.push_back(ids.tasks_id);
        if (!ids.join_id.empty()) argv.push_back(ids.join_id);
        if (argv.size() == 1) return {};
        Result<std::string> out = run(argv, ids.state_dir);
        if (!out) return out.error();
        return {};
    }
};

}  // namespace

std::unique_ptr<Engine> make_slurm_engine() { return std::make_unique<SlurmEngine>(); }

}  // namespace spt::farm
