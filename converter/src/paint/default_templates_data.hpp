// The compiled-in samples of the default templates (see default_templates_data.cpp, generated
// by converter/tools/make_templates.py).
#pragma once

namespace spt::paint::detail {

struct TemplateData {
    const char* name;
    int width, height;
    const unsigned char* samples;  // width * height coverage values, row-major
};

extern const TemplateData kDefaultTemplates[];
extern const int kDefaultTemplateCount;

}  // namespace spt::paint::detail
