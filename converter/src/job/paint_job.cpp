#include "job/paint_job.hpp"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "io/template_loader.hpp"
#include "job/option_table.hpp"
#include "spt/utf8.hpp"
#include "spt/version.hpp"

namespace spt::job {

const char* orient_name(paint::OrientMode m) {
    switch (m) {
        case paint::OrientMode::Edges: return "edges";
        case paint::OrientMode::Gradient: return "gradient";
        case paint::OrientMode::Random: return "random";
    }
    return "?";
}

std::string PaintJob::canonical() const {
    std::vector<const OptionRow*> ranked;
    for (const OptionRow& r : option_rows())
        if (r.canon_rank > 0 && r.canon) ranked.push_back(&r);
    std::stable_sort(ranked.begin(), ranked.end(),
                     [](const OptionRow* a, const OptionRow* b) { return a->canon_rank < b->canon_rank; });
    std::ostringstream s;
    for (const OptionRow* r : ranked) r->canon(s, *this);
    const std::string text = s.str();
    return text.empty() ? text : text.substr(1);  // every row writes " key=value"
}

std::vector<std::pair<std::string, std::string>> painting_metadata(const PaintJob& o) {
    return {
        {"software", std::string("spt ") + library_version()},
        {"source", printable_text(std::filesystem::path(o.input).filename().string())},  // names need not be UTF-8
        {"painter.seed", std::to_string(o.paint.seed)},
        {"painter.options", printable_text(o.canonical())},
    };
}

Result<std::vector<Template>> paint_templates(const std::string& templates_dir) {
    if (templates_dir.empty()) return paint::default_templates();
    return io::load_templates(templates_dir);
}

}  // namespace spt::job
