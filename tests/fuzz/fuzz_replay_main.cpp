// Without libFuzzer: replays every file of a seed corpus folder through the target, so that
// the corpora run as ordinary regression tests.  usage: <target> <corpus_dir>...
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int main(int argc, char** argv) {
    size_t files = 0;
    for (int i = 1; i < argc; ++i) {
        std::error_code ec;
        for (const auto& e : std::filesystem::directory_iterator(argv[i], ec)) {
            if (!e.is_regular_file()) continue;
            std::ifstream f(e.path(), std::ios::binary);
            std::vector<uint8_t> b((std::istreambuf_iterator<char>(f)), {});
            LLVMFuzzerTestOneInput(b.data(), b.size());
            ++files;
        }
        if (ec) { std::fprintf(stderr, "%s: %s\n", argv[i], ec.message().c_str()); return 1; }
    }
    std::printf("replayed %zu inputs\n", files);
    return files ? 0 : 1;
}
