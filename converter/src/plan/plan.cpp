#include "plan/plan.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "plan/bounded_file.hpp"
#include "spt/atomic_file.hpp"
#include "spt_json/json.hpp"
#include "spt_json/write.hpp"

namespace spt::plan {

namespace {

json::Doc body(const Plan& p, bool with_id) {
    json::Doc j = json::Doc::object();
    j["format"] = "spt-plan";
    j["version"] = p.version;
    if (with_id) j["id"] = p.id;
    j["spt_version"] = p.spt_version;
    j["input"] = p.input;
    j["frames"] = {{"first", int64_t(p.first)}, {"last", int64_t(p.last)}, {"count", p.frames()}};
    j["canvas"] = {{"width", p.width}, {"height", p.height}};
    j["fps"] = p.fps;
    j["seed"] = std::to_string(p.seed);
    j["keyframe_interval"] = p.keyframe_interval;
    j["max_task_frames"] = int64_t(p.max_task_frames);
    if (!p.cut_scan.empty()) {
        j["cut_scan"] = p.cut_scan;
        j["cut_step"] = p.cut_step;
        j["cut_history"] = p.cut_history;
    }
    j["cuts"] = p.cuts;
    json::Doc& job = j["job"] = json::Doc::object();
    for (const JobOption& o : p.job) {
        if (o.flag) job[o.name] = true;
        else if (o.list) job[o.name] = o.values;
        else job[o.name] = o.values.empty() ? std::string() : o.values.front();
    }
    json::Doc& shots = j["shots"] = json::Doc::array();
    for (const Shot& s : p.shots)
        shots.push_back({{"index", uint64_t(s.index)}, {"first", int64_t(s.first)}, {"last", int64_t(s.last)},
                         {"frames", s.frames()}, {"seed", std::to_string(s.seed)}, {"starts_at_cut", s.starts_at_cut},
                         {"key_frames", s.key_frames}});
    return j;
}

struct Fields {
    const json::Value& obj;
    const std::string& src;
    std::string err;
    std::string at(const json::Value& v) const { return src + ":" + std::to_string(v.line) + ": "; }
    const json::Value* need(const json::Value& o, const char* key, json::Type t) {
        const json::Value* v = o.find(key);
        if (!v) { if (err.empty()) err = at(o) + "missing \"" + key + "\""; return nullptr; }
        if (v->type != t) { if (err.empty()) err = at(*v) + "\"" + key + "\" must be a " + json::type_name(t); return nullptr; }
        return v;
    }
    bool integer(const json::Value& o, const char* key, long lo, long hi, long& out) {
        const json::Value* v = need(o, key, json::Type::Number);
        if (!v) return false;
        char* end = nullptr;
        errno = 0;
        const long x = std::strtol(v->text.c_str(), &end, 10);
        if (errno || *end || x < lo || x > hi) {
            if (err.empty()) err = at(*v) + "\"" + key + "\" must be an integer " + std::to_string(lo) + ".." + std::to_string(hi);
            return false;
        }
        out = x;
        return true;
    }
    bool u64_text(const json::Value& o, const char* key, uint64_t& out) {
        const json::Value* v = need(o, key, json::Type::String);
        if (!v) return false;
        char* end = nullptr;
        errno = 0;
        const unsigned long long x = std::strtoull(v->text.c_str(), &end, 10);
        if (v->text.empty() || v->text[0] == '-' || errno || *end) {
            if (err.empty()) err = at(*v) + "\"" + key + "\" must be a decimal string of an unsigned 64-bit integer";
            return false;
        }
        out = x;
        return true;
    }
    bool text(const json::Value& o, const char* key, std::string& out) {
        const json::Value* v = need(o, key, json::Type::String);
        if (v) out = v->text;
        return v != nullptr;
    }
};

// A job's option names are spelt as on the command line ("max-strokes"); which of them a task
// may take is the option table's to say when the task reads its job (job/plan_job.hpp).
bool option_name(const std::string& n) {
    if (n.empty() || n.size() > 64 || n[0] < 'a' || n[0] > 'z') return false;
    return n.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789-") == std::string::npos;
}

Status read_job(const json::Value& job, Fields& f, std::vector<JobOption>& out) {
    for (const json::Member& m : job.members) {
        const std::string& name = m.first;
        const json::Value& v = m.second;
        if (!option_name(name))
            return make_error(Code::InvalidArgument, f.at(v) + "\"job\" key '" + name + "' is not an option name");
        JobOption o;
        o.name = name;
        if (v.type == json::Type::Bool && v.boolean) {
            o.flag = true;
        } else if (v.is_string()) {
            o.values.push_back(v.text);
        } else if (v.type == json::Type::Array) {
            o.list = true;
            for (const json::Value& x : v.items) {
                if (!x.is_string()) return make_error(Code::InvalidArgument, f.at(x) + "\"job\" option '" + name + "' holds strings");
                o.values.push_back(x.text);
            }
        } else {
            return make_error(Code::InvalidArgument, f.at(v) + "\"job\" option '" + name + "' must be true, a string or strings");
        }
        out.push_back(std::move(o));
    }
    return {};
}

}  // namespace

std::string to_json(const Plan& p, bool with_id) {
    return json::dump(body(p, with_id), 2) + "\n";
}

std::string compute_id(const Plan& p) {
    const std::string t = to_json(p, false);
    uint64_t h = 0xcbf29ce484222325ull;
    for (unsigned char c : t) h = (h ^ c) * 0x100000001b3ull;
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", (unsigned long long)h);
    return buf;
}

Result<Plan> parse_plan(const std::string& text, const std::string& src) {
    Result<json::Value> doc = json::parse(text, src, plan_parse_limits());
    if (!doc) return doc.error();
    const json::Value& root = *doc;
    if (!root.is_object()) return make_error(Code::InvalidArgument, src + ": a plan is a JSON object");
    Fields f{root, src, {}};
    Plan p;
    std::string format;
    long v = 0;
    if (f.text(root, "format", format) && format != "spt-plan")
        return make_error(Code::InvalidArgument, src + ": \"format\" is '" + format + "', not 'spt-plan'");
    if (f.integer(root, "version", 0, 1000000, v) && v != kPlanVersion)
        return make_error(Code::Unsupported, src + ": plan version " + std::to_string(v) + "; this spt reads version " +
                                                 std::to_string(kPlanVersion) + ": plan again with this spt (spt plan IN -o " +
                                                 src + " and the options the plan was made with)");
    f.text(root, "id", p.id);
    f.text(root, "spt_version", p.spt_version);
    f.text(root, "input", p.input);
    if (const json::Value* fr = f.need(root, "frames", json::Type::Object)) {
        f.integer(*fr, "first", 0, 0x7FFFFFFF, p.first);
        f.integer(*fr, "last", 0, 0x7FFFFFFF, p.last);
    }
    long w = 0, h = 0;
    if (const json::Value* c = f.need(root, "canvas", json::Type::Object)) {
        f.integer(*c, "width", 1, 1 << 20, w);
        f.integer(*c, "height", 1, 1 << 20, h);
    }
    p.width = uint32_t(w);
    p.height = uint32_t(h);
    f.text(root, "fps", p.fps);
    f.u64_text(root, "seed", p.seed);
    long kfi = 0;
    if (f.integer(root, "keyframe_interval", 1, 1000000, kfi)) p.keyframe_interval = int(kfi);
    f.integer(root, "max_task_frames", 0, 0x7FFFFFFF, p.max_task_frames);
    // Added within version 1: plans written before them scanned every frame.
    if (root.find("cut_scan")) {
        f.text(root, "cut_scan", p.cut_scan);
        long step = 1;
        if (f.integer(root, "cut_step", 0, 1000000, step)) p.cut_step = int(step);
        long hist = 0;
        if (f.integer(root, "cut_history", 0, 1000000, hist)) p.cut_history = int(hist);
        if (f.err.empty() && p.cut_scan != "full" && p.cut_scan != "sampled" && p.cut_scan != "tasks")
            return make_error(Code::InvalidArgument, src + ": \"cut_scan\" must be \"full\", \"sampled\" or \"tasks\"");
    }
    if (const json::Value* c = f.need(root, "cuts", json::Type::Array))
        for (const json::Value& x : c->items) {
            if (!x.is_number()) return make_error(Code::InvalidArgument, f.at(x) + "\"cuts\" holds frame numbers");
            p.cuts.push_back(std::strtol(x.text.c_str(), nullptr, 10));
        }
    if (const json::Value* job = f.need(root, "job", json::Type::Object))
        if (Status st = read_job(*job, f, p.job); !st) return st.error();
    if (const json::Value* shots = f.need(root, "shots", json::Type::Array)) {
        for (const json::Value& s : shots->items) {
            if (!s.is_object()) return make_error(Code::InvalidArgument, f.at(s) + "a shot is an object");
            Shot shot;
            long idx = 0;
            f.integer(s, "index", 0, 0x7FFFFFFF, idx);
            shot.index = size_t(idx);
            f.integer(s, "first", 0, 0x7FFFFFFF, shot.first);
            f.integer(s, "last", 0, 0x7FFFFFFF, shot.last);
            f.u64_text(s, "seed", shot.seed);
            if (const json::Value* c = f.need(s, "starts_at_cut", json::Type::Bool)) shot.starts_at_cut = c->boolean;
            if (const json::Value* k = f.need(s, "key_frames", json::Type::Array))
                for (const json::Value& x : k->items) shot.key_frames.push_back(std::strtol(x.text.c_str(), nullptr, 10));
            if (!f.err.empty()) break;
            // The shots cover the input in order, without gaps or overlaps.
            const long expect = p.shots.empty() ? p.first : p.shots.back().last + 1;
            if (shot.index != p.shots.size() || shot.first != expect || shot.last < shot.first)
                return make_error(Code::InvalidArgument, f.at(s) + "shot " + std::to_string(idx) + " (" +
                                                             std::to_string(shot.first) + "-" + std::to_string(shot.last) +
                                                             ") does not follow on: expected shot " +
                                                             std::to_string(p.shots.size()) + " from frame " +
                                                             std::to_string(expect));
            p.shots.push_back(std::move(shot));
        }
    }
    if (!f.err.empty()) return make_error(Code::InvalidArgument, f.err);
    if (p.shots.empty()) return make_error(Code::InvalidArgument, src + ": the plan has no shots");
    if (p.shots.back().last != p.last)
        return make_error(Code::InvalidArgument, src + ": the shots end at frame " + std::to_string(p.shots.back().last) +
                                                     ", the plan's frames at " + std::to_string(p.last));
    // The task's command line is built from these: none may pass for an option.
    if (p.input.empty() || p.input[0] == '-')
        return make_error(Code::InvalidArgument, src + ": \"input\" '" + p.input + "' is not a path");
    if (p.fps.empty() || p.fps.find_first_not_of("0123456789./") != std::string::npos)
        return make_error(Code::InvalidArgument, src + ": \"fps\" '" + p.fps + "' is not a frame rate");
    if (p.id != compute_id(p))
        return make_error(Code::InvalidArgument, src + ": \"id\" is not the plan's checksum: the plan was edited by hand "
                                                     "(write a new one with spt plan)");
    return p;
}

Result<Plan> read_plan(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return make_error(Code::IoError, path + ": no such plan file");
    Result<std::string> text = read_bounded_file(path, kMaxPlanFileBytes, "plan file");
    if (!text) return text.error();
    return parse_plan(*text, path);
}

Status write_plan(const Plan& p, const std::string& path) {
    // Through an unnamed temporary linked into place (spt/atomic_file.hpp): never half-written,
    // and no symlink at a temporary name can redirect it.
    const std::string text = to_json(p);
    return write_file_atomic(path, text.data(), text.size());
}

std::vector<std::pair<long, long>> split_shot(long first, long last, int keyframe_interval, long max_frames) {
    const long n = last - first + 1;
    if (max_frames <= 0 || n <= max_frames) return {{first, last}};
    const long kfi = std::max(1, keyframe_interval);
    // Split on whole key frame intervals when one fits in a task; else on max_frames.
    const long unit = kfi <= max_frames ? kfi : 1;
    const long units = (n + unit - 1) / unit;
    const long per_task = std::max<long>(1, max_frames / unit);  // units a task may hold
    const long pieces = (units + per_task - 1) / per_task;
    std::vector<std::pair<long, long>> out;
    long at = first;
    for (long k = 0; k < pieces; ++k) {
        // Spread the units evenly: piece k ends after unit floor((k + 1) * units / pieces).
        const long end_unit = (k + 1) * units / pieces;
        const long end = std::min(last, first + end_unit * unit - 1);
        out.push_back({at, end});
        at = end + 1;
    }
    return out;
}

}  // namespace spt::plan
