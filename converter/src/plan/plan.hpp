// A farm plan (README.md): the shots of one input, each a task that paints on any machine to
// the same bytes, and everything those tasks need. Read and written as versioned JSON.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "spt/result.hpp"

namespace spt::plan {

// Version 2 stores the job (the painting options by name); version 1 stored them as argv
// ("paint_args") and is refused with a word on planning again.
inline constexpr int kPlanVersion = 2;

// One option of the job every task paints (the option table's painting rows,
// converter/src/job/option_table.hpp): a flag, one value, or a repeatable option's values.
struct JobOption {
    std::string name;
    std::vector<std::string> values;  // a flag: none
    bool flag = false;
    bool list = false;                // written as an array even with one value
};

struct Shot {
    size_t index = 0;
    long first = 0, last = 0;       // source frame numbers, inclusive
    uint64_t seed = 0;              // the painter's seed for this shot (from the plan's seed)
    bool starts_at_cut = false;     // false: a long shot split at a forced key frame
    std::vector<long> key_frames;   // forced key frames (the first, then every keyframe_interval)
    uint64_t frames() const { return uint64_t(last - first + 1); }
};

struct Plan {
    int version = kPlanVersion;
    std::string id;                 // 16 hex digits: FNV-1a 64 of the rest (compute_id)
    std::string spt_version;        // of the spt that wrote the plan; tasks need the same painter
    std::string input;              // absolute path or pattern
    long first = 0, last = -1;      // source frame numbers of the whole input
    uint32_t width = 0, height = 0;
    std::string fps;                // "num/den"
    uint64_t seed = 1;
    int keyframe_interval = 100;
    long max_task_frames = 0;       // 0: shots are never split
    std::vector<long> cuts;         // source numbers that start a shot (the first frame too)
    // How the cuts were found: "full" (every frame), "sampled" every cut_step frames with
    // verdicts on cut_history pairs (1 and 0 for "full"), or "tasks" (by each task as it paints:
    // `cuts` holds the first frame only; 0 and 0); "" in plans written before these members (not
    // written back: the id stays).
    std::string cut_scan;
    int cut_step = 1;
    int cut_history = 0;            // the sampled scan's verdict history (0 for "full")
    std::vector<JobOption> job;     // the options every task paints with (README.md)
    std::vector<Shot> shots;
    uint64_t frames() const { return last >= first ? uint64_t(last - first + 1) : 0; }
};

// The plan as JSON (README.md's layout); `with_id` false leaves "id" out (what the id hashes).
std::string to_json(const Plan& p, bool with_id = true);
std::string compute_id(const Plan& p);
// Parses and checks a plan: the version, shots that cover first..last in order, seeds.
Result<Plan> parse_plan(const std::string& text, const std::string& source);
Result<Plan> read_plan(const std::string& path);
// Writes `path` through a temporary file renamed into place.
Status write_plan(const Plan& p, const std::string& path);

// Pieces of a shot first..last of at most `max_frames` frames each (0: one piece), as equal as
// whole key frame intervals allow: every piece but the last starts a multiple of
// `keyframe_interval` after the shot, so the pieces' forced key frames are the shot's own.
std::vector<std::pair<long, long>> split_shot(long first, long last, int keyframe_interval, long max_frames);

}  // namespace spt::plan
