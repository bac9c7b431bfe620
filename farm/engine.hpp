// The one interface a farm manager sits behind: a job of tasks (one per shot, each a command
// that paints one shot file, retried up to a limit) and a join that runs once every task
// succeeded. spt keeps the shot files, logs and task markers in the plan's state folder
// (farm_job.hpp), so an engine only queues commands and says which of its tasks are waiting
// or running. Slurm is slurm_engine.cpp; README.md maps Flamenco, OpenCue and Open Job
// Description onto the same calls.
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "spt/result.hpp"

namespace spt::farm {

struct Task {
    size_t shot = 0;                   // the plan's shot index
    std::vector<std::string> command;  // argv: the wrapper that paints the shot, with retries
    std::string log;                   // where its output goes
};

struct FarmJob {
    std::string name;                  // a job name for the farm's queue
    std::string state_dir;             // absolute; scripts may be written here
    std::vector<Task> tasks;           // may be empty (every shot already painted)
    std::vector<std::string> join;     // argv of the join, run after every task succeeded
    std::string join_log;
    int retries = 2;                   // attempts after the first, per task
    std::string partition;             // queue / pool / partition; empty = the farm's default
    std::vector<std::string> extra;    // the engine's own options, passed through as they are
};

// What submit() returned: the engine's ids of the task group and of the join.
struct Submitted {
    std::string engine, tasks_id, join_id;
    // The plan's state folder: the engine's commands write their stderr into its logs/ (set by
    // submit() and by farm_status(); not stored in job.json, which sits in that folder).
    std::string state_dir;
};

enum class QueueState { Pending, Running };

class Engine {
public:
    virtual ~Engine() = default;
    virtual std::string name() const = 0;
    // Queues the tasks and the join (which must not start before all tasks succeeded, and
    // must never start if one finally failed).
    virtual Result<Submitted> submit(const FarmJob& job) = 0;
    // The tasks of `ids` the farm still holds, by shot: waiting or running. Finished tasks
    // are absent (their markers in the state folder say how they ended).
    virtual Result<std::map<size_t, QueueState>> queued_tasks(const Submitted& ids) = 0;
    // True while the join is waiting or running.
    virtual Result<bool> join_queued(const Submitted& ids) = 0;
    virtual Status cancel(const Submitted& ids) = 0;
};

std::unique_ptr<Engine> make_slurm_engine();

}  // namespace spt::farm
