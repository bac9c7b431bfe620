// libFuzzer target: the Lottie importer (JSON, keyframes, shapes, layers) on arbitrary bytes.
#include "import_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const spt::import::Importer* imp = spt::import::find_importer("lottie");
    return spt_fuzz::import_bytes(*imp, data, size);
}
