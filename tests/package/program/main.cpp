// Prints a .spt file's size and frame count, and renders its last frame: a user's first program.
#include <cstdio>
#include <spt/spt.hpp>

int main(int argc, char** argv) {
    if (argc != 2) return 2;
    auto r = spt::Reader::open(argv[1]);
    if (!r) return std::fprintf(stderr, "%s\n", r.error().message.c_str()), 1;
    const spt::StreamInfo& info = (*r)->info();
    const size_t n = (*r)->frames().size();
    auto live = (*r)->strokes_at(uint32_t(n - 1));
    auto rend = spt::Renderer::create(info.header, info.templates);
    if (!live || !rend) return std::fprintf(stderr, "cannot decode the last frame\n"), 1;
    spt::Canvas c(info.header.width, info.header.height);
    if (auto st = (*rend)->render(c, **live); !st) return std::fprintf(stderr, "%s\n", st.error().message.c_str()), 1;
    std::printf("%ux%u, %zu frames, %zu strokes live at the last\n", info.header.width, info.header.height, n, (*live)->size());
    return 0;
}
