// Reading the small JSON files of plans and farm state: the size is checked against a cap
// before anything is read or allocated, so a huge (or sparse, or endless) file is refused
// at once instead of being read into memory and then found wrong.
#pragma once

#include <cstddef>
#include <string>

#include "spt/result.hpp"
#include "spt_json/json.hpp"

namespace spt::plan {

// A plan or farm state JSON file: at most 32 MiB and 2^21 JSON values (a plan of 40,000 shots
// is about 7 MiB and 500,000 values), so its parse tree stays within a few hundred MB.
inline constexpr size_t kMaxPlanFileBytes = size_t(32) << 20;
inline constexpr size_t kMaxPlanValues = size_t(1) << 21;

// The JSON parser's limits for such files.
json::ParseLimits plan_parse_limits();

// The file's bytes if it is a regular file of at most `max_bytes`; `what` names it in errors
// ("plan file", "farm state file").
Result<std::string> read_bounded_file(const std::string& path, size_t max_bytes, const char* what);

}  // namespace spt::plan
