// Fuzz target: a farm plan's JSON (converter/src/plan/plan.cpp over the shared JSON parser) on
// arbitrary bytes. It must return a plan or an error, never crash or hang; a plan it accepts
// must be written back as JSON that it accepts again, to the same plan.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "plan/plan.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    auto p = spt::plan::parse_plan(text, "fuzz-input");
    if (!p) return 0;
    const std::string again = spt::plan::to_json(*p);
    auto q = spt::plan::parse_plan(again, "fuzz-again");
    if (!q || spt::plan::to_json(*q) != again) std::abort();  // what it wrote, it must read
    return 0;
}
