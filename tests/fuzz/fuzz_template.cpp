// Fuzz target: the TMPL chunk payload decoder (raw and range-coded samples).
#include <cstddef>
#include <cstdint>

#include "container.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    spt::Limits lim;
    lim.max_template_side = 256;
    spt::Template t;
    (void)spt::detail::decode_tmpl(data, size, 0, lim, t);
    return 0;
}
