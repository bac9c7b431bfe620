// A plan on a farm, whatever the engine: the state folder beside the plan (PLAN.farm/: shot
// files, logs, task markers, the submission), which shots still need painting (a shot file
// kept from an earlier submission is reused when it verifies), the task and join wrappers the
// engine runs, and the status and progress of the whole job.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "farm/engine.hpp"
#include "plan/plan.hpp"
#include "spt/result.hpp"

namespace spt::farm {

// "dir/shot.plan.json" -> "dir/shot.plan.farm" (absolute).
std::string state_dir_for(const std::string& plan_path);
std::string shot_file(const std::string& state_dir, size_t shot);

struct SubmitOptions {
    std::string plan_path;
    std::string output;                // the joined file
    std::string partition;
    std::vector<std::string> extra;    // engine options, passed through
    int retries = 2;
    std::string spt;                   // the spt executable the tasks run (absolute)
};

struct SubmitReport {
    Submitted ids;
    std::vector<size_t> painting, reused;
    std::string state_dir;
};

Result<SubmitReport> submit_plan(Engine& engine, const SubmitOptions& o);

enum class ShotState { Done, Running, Pending, Failed, Lost };
const char* shot_state_name(ShotState s);

struct FarmStatus {
    plan::Plan plan;
    std::string state_dir, output;
    Submitted ids;
    std::vector<ShotState> shots;
    std::vector<int> attempts;          // per shot, attempts that ended
    std::vector<bool> reused;
    bool join_queued = false, joined = false;
    double elapsed = 0;                 // seconds since the submission
    uint64_t frames_painted = 0, frames_to_paint = 0;  // this submission's shots
    size_t count(ShotState s) const;
    double frames_per_second() const { return elapsed > 0 ? double(frames_painted) / elapsed : 0; }
    // One line: shots done/running/failed, frames per second over the farm, time left.
    std::string progress_line() const;
};

// `engine` null: the one the submission used.
Result<FarmStatus> farm_status(const std::string& plan_path, Engine* engine = nullptr);

}  // namespace spt::farm
