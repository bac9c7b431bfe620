// The metadata a farm plan's shot files carry (README.md "Shot files"), and the check `spt cat`
// runs on every part: a join of a plan's shots must hold each shot once, in order, complete.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "spt/concat.hpp"
#include "spt/result.hpp"
#include "spt/types.hpp"

namespace spt::plan {

inline constexpr const char* kPlanIdKey = "plan.id";        // the plan a file was painted from
inline constexpr const char* kPartShotKey = "part.shot";    // "K/N": shot K of the plan's N
inline constexpr const char* kPartFramesKey = "part.frames";  // "A-B": the shot's source frames

// The metadata entries of shot `shot` (of `shots`) of plan `id`, source frames first..last.
std::vector<std::pair<std::string, std::string>> shot_metadata(const std::string& id, size_t shot, size_t shots,
                                                               long first, long last);

// What a shot file says about itself; `is_shot` false when it carries no part.shot entry.
struct ShotTag {
    bool is_shot = false;
    std::string plan_id;
    size_t shot = 0, shots = 0;
    long first = 0, last = -1;
};
// Fails, naming `path`, when the entries are present but malformed.
Result<ShotTag> read_shot_tag(const std::string& path, const StreamInfo& info);

// Checks part `pos` of `count` parts of a join. A part that is a plan's shot must be shot
// `pos` of a plan of `count` shots, of the same plan as part 0, and hold all its frames
// (`frames` of them). `first` is part 0's tag (read by the caller).
Status check_join_part(size_t pos, size_t count, const std::string& path, const StreamInfo& info,
                       uint64_t frames, const ShotTag& first, const std::string& first_path);

// Join options whose check_part runs check_join_part on each of `parts` parts.
ConcatOptions join_options(size_t parts);

struct Plan;
// A shot file that a farm may keep instead of painting the shot again: complete, tagged as
// shot `shot` of `plan`, holding all its frames, every frame decoded and applied (spt verify's
// checks without rendering). The error says what is wrong, naming `path`.
Status verify_shot(const Plan& plan, size_t shot, const std::string& path);

}  // namespace spt::plan
