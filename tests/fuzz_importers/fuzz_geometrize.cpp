// libFuzzer target: the geometrize-json importer (and its text parser) on arbitrary bytes.
#include "import_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const spt::import::Importer* imp = spt::import::find_importer("geometrize-json");
    return spt_fuzz::import_bytes(*imp, data, size);
}
