#include "plan/plan_parts.hpp"

#include <cerrno>
#include <cstdlib>
#include <memory>

#include "plan/plan.hpp"
#include "spt/reader.hpp"

namespace spt::plan {

namespace {

const std::string* find(const StreamInfo& info, const std::string& key) {
    for (const auto& [k, v] : info.metadata)
        if (k == key) return &v;
    return nullptr;
}

bool parse_pair(const std::string& s, char sep, long& a, long& b) {
    const size_t at = s.find(sep, 1);
    if (at == std::string::npos) return false;
    char* end = nullptr;
    errno = 0;
    a = std::strtol(s.c_str(), &end, 10);
    if (errno || end != s.c_str() + at) return false;
    b = std::strtol(s.c_str() + at + 1, &end, 10);
    return !errno && *end == 0 && end != s.c_str() + at + 1;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> shot_metadata(const std::string& id, size_t shot, size_t shots,
                                                               long first, long last) {
    return {{kPlanIdKey, id},
            {kPartShotKey, std::to_string(shot) + "/" + std::to_string(shots)},
            {kPartFramesKey, std::to_string(first) + "-" + std::to_string(last)}};
}

Result<ShotTag> read_shot_tag(const std::string& path, const StreamInfo& info) {
    ShotTag t;
    const std::string* shot = find(info, kPartShotKey);
    if (!shot) return t;
    long k = -1, n = -1;
    if (!parse_pair(*shot, '/', k, n) || k < 0 || n < 1 || k >= n)
        return make_error(Code::Corrupt, path + ": metadata part.shot '" + *shot + "' is not K/N with 0 <= K < N");
    const std::string* frames = find(info, kPartFramesKey);
    if (!frames || !parse_pair(*frames, '-', t.first, t.last) || t.first < 0 || t.last < t.first)
        return make_error(Code::Corrupt, path + ": shot file without a sound part.frames entry (A-B)");
    const std::string* id = find(info, kPlanIdKey);
    if (!id || id->empty()) return make_error(Code::Corrupt, path + ": shot file without a plan.id entry");
    t.is_shot = true;
    t.plan_id = *id;
    t.shot = size_t(k);
    t.shots = size_t(n);
    return t;
}

Status check_join_part(size_t pos, size_t count, const std::string& path, const StreamInfo& info, uint64_t frames,
                       const ShotTag& first, const std::string& first_path) {
    Result<ShotTag> tag = read_shot_tag(path, info);
    if (!tag) return tag.error();
    if (!tag->is_shot && !first.is_shot) return {};
    if (!tag->is_shot)
        return make_error(Code::InvalidArgument, path + ": is not a shot of plan " + first.plan_id + " (" + first_path +
                                                     " is); join a plan's shots only with each other");
    if (!first.is_shot)
        return make_error(Code::InvalidArgument, path + ": is shot " + std::to_string(tag->shot) + " of plan " +
                                                     tag->plan_id + ", but " + first_path + " is not a shot file");
    if (tag->plan_id != first.plan_id)
        return make_error(Code::InvalidArgument, path + ": is a shot of plan " + tag->plan_id + ", " + first_path +
                                                     " of plan " + first.plan_id);
    const std::string of = " of plan " + tag->plan_id + " (" + std::to_string(tag->shots) + " shots)";
    if (tag->shot != pos) {
        if (tag->shot > pos)
            return make_error(Code::InvalidArgument, path + ": is shot " + std::to_string(tag->shot) + of + " where shot " +
                                                         std::to_string(pos) + " belongs: shot " + std::to_string(pos) +
                                                         " is missing");
        return make_error(Code::InvalidArgument, path + ": is shot " + std::to_string(tag->shot) + of + " again, or out of "
                                                     "order, at place " + std::to_string(pos) + ": an extra shot");
    }
    if (pos + 1 == count && count < tag->shots)
        return make_error(Code::InvalidArgument, path + ": is the last part given but shot " + std::to_string(pos) + of +
                                                     ": shots " + std::to_string(count) + "-" +
                                                     std::to_string(tag->shots - 1) + " are missing");
    if (count > tag->shots && pos + 1 == tag->shots)
        return make_error(Code::InvalidArgument, "the join has " + std::to_string(count) + " parts, but plan " + tag->plan_id +
                                                     " has " + std::to_string(tag->shots) + " shots: the parts after " + path +
                                                     " are extra");
    const uint64_t want = uint64_t(tag->last - tag->first + 1);
    if (frames != want)
        return make_error(Code::InvalidArgument, path + ": shot " + std::to_string(pos) + of + " holds " +
                                                     std::to_string(frames) + " of its " + std::to_string(want) +
                                                     " frames (" + std::to_string(tag->first) + "-" +
                                                     std::to_string(tag->last) + "): it was interrupted; paint it again");
    return {};
}

ConcatOptions join_options(size_t parts) {
    struct First {
        ShotTag tag;
        std::string path;
    };
    auto first = std::make_shared<First>();
    ConcatOptions co;
    co.check_part = [first, parts](size_t pos, const std::string& path, const StreamInfo& info, uint64_t frames) -> Status {
        if (pos == 0) {
            Result<ShotTag> t = read_shot_tag(path, info);
            if (!t) return t.error();
            first->tag = *t;
            first->path = path;
        }
        return check_join_part(pos, parts, path, info, frames, first->tag, first->path);
    };
    return co;
}

Status verify_shot(const Plan& plan, size_t shot, const std::string& path) {
    if (shot >= plan.shots.size()) return make_error(Code::InvalidArgument, path + ": the plan has no shot " + std::to_string(shot));
    Result<std::unique_ptr<Reader>> r = Reader::open(path);
    if (!r) return make_error(r.error().code, r.error().message.rfind(path, 0) == 0 ? r.error().message : path + ": " + r.error().message);
    Reader& rd = **r;
    if (!rd.complete()) return make_error(Code::Truncated, path + ": incomplete (no end chunk)");
    if (!rd.warnings().empty()) return make_error(Code::Corrupt, path + ": " + rd.warnings().front().message);
    Result<ShotTag> tag = read_shot_tag(path, rd.info());
    if (!tag) return tag.error();
    const Shot& s = plan.shots[shot];
    if (!tag->is_shot || tag->plan_id != plan.id || tag->shot != shot || tag->shots != plan.shots.size() ||
        tag->first != s.first || tag->last != s.last)
        return make_error(Code::InvalidArgument, path + ": is not shot " + std::to_string(shot) + " of plan " + plan.id);
    if (rd.frames().size() != s.frames())
        return make_error(Code::InvalidArgument, path + ": holds " + std::to_string(rd.frames().size()) + " of its " +
                                                     std::to_string(s.frames()) + " frames");
    for (size_t i = 0; i < rd.frames().size(); ++i) {
        Result<const std::vector<Stroke>*> live = rd.strokes_at(i);
        if (!live) return make_error(live.error().code, path + ": frame " + std::to_string(i) + ": " + live.error().message);
    }
    return {};
}

}  // namespace spt::plan
