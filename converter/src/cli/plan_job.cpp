#include "cli/plan_job.hpp"

#include "job/option_table.hpp"

namespace spt::cli {

std::vector<plan::JobOption> plan_job(const PaintCommandOptions& o) {
    std::vector<plan::JobOption> job;
    for (const job::OptionRow& r : job::option_rows()) {
        if (r.scope != job::OptionScope::Painting || !r.get) continue;
        std::vector<std::string> values = r.get(o);
        if (values.empty()) continue;
        plan::JobOption opt;
        opt.name = r.name;
        opt.flag = r.kind == job::OptionKind::Flag;
        opt.list = r.kind == job::OptionKind::List;
        if (!opt.flag) opt.values = std::move(values);
        job.push_back(std::move(opt));
    }
    return job;
}

std::string apply_plan_job(const plan::Plan& p, const std::string& plan_path, PaintCommandOptions& o) {
    std::vector<std::string> given;
    for (const plan::JobOption& opt : p.job) {
        auto refuse = [&](const std::string& why) {
            return plan_path + ": \"job\" option '" + opt.name + "' " + why + " (a plan may hold only painter options)";
        };
        const job::OptionRow* r = job::find_option(opt.name);
        if (!r || r->scope != job::OptionScope::Painting) return refuse("is not a painter option");
        const bool flag = r->kind == job::OptionKind::Flag, list = r->kind == job::OptionKind::List;
        if (flag != opt.flag || list != opt.list || (!flag && !list && opt.values.size() != 1))
            return refuse(flag ? "is a flag: true" : list ? "takes a list of strings" : "takes one string");
        given.push_back(opt.name);
        for (const std::string& v : flag ? std::vector<std::string>{"true"} : opt.values)
            if (std::string e = job::apply_option(*r, v, o); !e.empty()) return plan_path + ": \"job\": " + e;
    }
    if (std::string e = job::finish_job(o, given); !e.empty()) return plan_path + ": \"job\": " + e;
    return {};
}

}  // namespace spt::cli
