// Writes a one-frame .spt file with spt::Writer, reads it back with spt::Reader and renders it
// with spt::Renderer: proof that the installed headers and library are complete and usable.
#include <cstdio>
#include <spt/spt.hpp>

static int fail(const char* what, const spt::Error& e) {
    std::fprintf(stderr, "%s: %s\n", what, e.message.c_str());
    return 1;
}

int main(int argc, char** argv) {
    if (argc != 2) return 2;
    const char* path = argv[1];
    spt::StreamInfo info;
    info.header.width = 32;
    info.header.height = 24;
    info.header.frame_count = 1;
    info.header.background = {255, 255, 255};
    info.header.sets = {{8, 4}};
    info.header.orientations = spt::default_orientations(8);
    spt::Template disc;
    disc.kind = spt::TemplateKind::Ellipse;
    info.templates = {disc};
    info.metadata = {{"generator", "spt consumer test"}};

    auto w = spt::Writer::create(path, info);
    if (!w) return fail("create", w.error());
    spt::Frame f;
    f.index = 0;
    f.type = spt::FrameType::Key;
    spt::StampStroke s;
    s.x = 16 * 16 + 8;
    s.y = 12 * 16 + 8;
    s.color = {200, 10, 10, 255};
    f.added.push_back(spt::Stroke::make_stamp(s));
    if (auto st = (*w)->append(f); !st) return fail("append", st.error());
    if (auto st = (*w)->finish(); !st) return fail("finish", st.error());

    auto r = spt::Reader::open(path);
    if (!r) return fail("open", r.error());
    if ((*r)->frames().size() != 1) return std::fprintf(stderr, "frame count\n"), 1;
    auto live = (*r)->strokes_at(0);
    if (!live) return fail("strokes_at", live.error());
    if ((*live)->size() != 1 || !((**live)[0] == f.added[0])) return std::fprintf(stderr, "strokes differ\n"), 1;

    auto rend = spt::Renderer::create((*r)->info().header, (*r)->info().templates);
    if (!rend) return fail("renderer", rend.error());
    spt::Canvas c(32, 24);
    if (auto st = (*rend)->render(c, **live); !st) return fail("render", st.error());
    const uint8_t* centre = c.row(12) + 16 * 3;
    const uint8_t* corner = c.row(0);
    if (centre[0] != 200 || centre[1] != 10 || corner[0] != 255)
        return std::fprintf(stderr, "rendered pixels unexpected: %d %d %d / %d\n", centre[0], centre[1], centre[2], corner[0]), 1;
    std::printf("consumer ok: spt %s, %zu frame, %zu stroke\n", spt::library_version(), (*r)->frames().size(),
                (*live)->size());
    return 0;
}
