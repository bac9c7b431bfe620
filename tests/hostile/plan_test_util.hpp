// Plans for the crafted-plan tests: a tiny PNG sequence planned with spt, and an edit of its
// job re-signed the way anyone can (the id is a checksum, not a signature).
#pragma once

#include <cstdio>
#include <fstream>

#include "converter/cli_test_util.hpp"
#include "spt_json/json.hpp"

namespace spt_test {

// seq/f.0001.png .. f.0002.png in `d` (copies of a small valid PNG); returns the pattern.
inline std::string tiny_sequence(const TempDir& d) {
    fs::create_directories(d.path / "seq");
    const fs::path src = fs::path(SPT_SOURCE_DIR) / "tests/hostile/inputs/good.png";
    for (const char* n : {"f.0001.png", "f.0002.png"}) fs::copy_file(src, d.path / "seq" / n);
    return (d.path / "seq" / "f.####.png").string();
}

// Plans the tiny sequence to `plan`, a shot a frame; an empty string when spt plan failed.
inline std::string tiny_plan(const TempDir& d, const std::string& plan) {
    const RunResult r = run_spt(d, {"plan", tiny_sequence(d), "-o", plan, "--max-strokes", "50", "--max-task-frames", "1",
                                         "--progress", "none"});
    EXPECT_EQ(r.code, 0) << r.err;
    return r.code == 0 ? slurp(plan) : std::string();
}

// The plan text with its id recomputed: FNV-1a 64 of the text without the id line.
inline std::string resign(std::string text) {
    const size_t at = text.find("\n  \"id\": \"");
    if (at == std::string::npos) return text;
    const size_t end = text.find('\n', at + 1);
    const std::string body = text.substr(0, at) + text.substr(end);
    uint64_t h = 0xcbf29ce484222325ull;
    for (unsigned char c : body) h = (h ^ c) * 0x100000001b3ull;
    char id[17];
    std::snprintf(id, sizeof id, "%016llx", (unsigned long long)h);
    return body.substr(0, at) + "\n  \"id\": \"" + id + "\"," + body.substr(at);
}

// The plan with `members` (JSON text: "\"name\": value") added to its job, re-signed.
inline std::string with_job(const std::string& plan_text, const std::vector<std::string>& members) {
    std::string t = plan_text;
    const size_t job = t.find("\"job\": {");
    if (job == std::string::npos) return t;
    std::string add;
    for (const std::string& m : members) add += "\n    " + m + ",";
    t.insert(job + 8, add);
    return resign(t);
}

}  // namespace spt_test
