// Outputs on a full disk and images that are not what they say (issue 36 item 11): out of space
// with --preview the .spt was written but the message named only the preview; an mp4 render
// said "OpenCV cannot create a .mp4 video here"; --web left a partial folder; an EXR of only Z,
// only A, or R and G was painted as grey without a word; a 100000x100000 display window was
// painted as its 64x48 data window. The full disks are small tmpfs mounts (the tests run as
// root: a mount that fails is a failure, not a skip).
#include <sys/mount.h>

#include <OpenImageIO/imageio.h>

#include "converter/cli_test_util.hpp"
#include "io/image_io.hpp"

using namespace spt_test;

namespace {

// A tmpfs of `kib` KiB at `dir` (made), unmounted when it goes.
struct SmallDisk {
    std::string dir;
    bool ok = false;
    SmallDisk(const std::string& d, int kib) : dir(d) {
        fs::create_directories(dir);
        const std::string opt = "size=" + std::to_string(kib) + "k";
        ok = ::mount("tmpfs", dir.c_str(), "tmpfs", MS_NOSUID | MS_NODEV, opt.c_str()) == 0;
        if (!ok) ADD_FAILURE() << "cannot mount a tmpfs at " << dir << ": " << std::strerror(errno);
    }
    ~SmallDisk() {
        if (ok) ::umount2(dir.c_str(), MNT_DETACH);
    }
    // Fills it but for about `free_kib` KiB.
    void fill(int total_kib, int free_kib) const {
        const std::string junk(size_t(total_kib - free_kib) * 1024, 'x');
        write_text(dir + "/fill", junk);
    }
    std::vector<std::string> names() const {
        std::vector<std::string> v;
        for (const auto& e : fs::directory_iterator(dir))
            if (e.path().filename() != "fill") v.push_back(e.path().filename().string());
        std::sort(v.begin(), v.end());
        return v;
    }
};

std::string noise_png(const TempDir& d, const std::string& name, uint32_t w, uint32_t h, uint32_t seed) {
    std::vector<uint8_t> px(size_t(w) * h * 3);
    std::mt19937 rng(seed);
    for (auto& p : px) p = uint8_t(rng());
    const std::string path = d.file(name);
    EXPECT_TRUE(spt::io::write_image(path, w, h, px.data()).ok());
    return path;
}

// A 64x48 half EXR of `names` (each channel 0.5), its display window `full` square when > 0.
std::string exr(const TempDir& d, const std::string& name, const std::vector<std::string>& names, int full = 0) {
    OIIO::ImageSpec spec(64, 48, int(names.size()), OIIO::TypeDesc::HALF);
    spec.channelnames = names;
    spec.alpha_channel = -1;
    if (full > 0) spec.full_width = spec.full_height = full;
    const std::vector<float> px(size_t(64) * 48 * names.size(), 0.5f);
    const std::string path = d.file(name);
    auto out = OIIO::ImageOutput::create(path);
    EXPECT_TRUE(out && out->open(path, spec));
    EXPECT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
    out->close();
    return path;
}

}  // namespace

TEST(HostileOutputs, APreviewOnAFullDiskSaysTheSptIsComplete) {
    TempDir d;
    // About 1 KB of painting (one 4 KiB page) and a 19 KB preview.
    const std::string in = noise_png(d, "n.png", 256, 256, 3);
    SmallDisk disk(d.file("disk"), 12);
    const auto r = run_spt(d, {"paint", in, "-o", disk.dir + "/o.spt", "--max-strokes", "400", "--preview", disk.dir + "/p.png"});
    EXPECT_TRUE(failed_with(r, 1, {"--preview " + disk.dir + "/p.png", "No space left on device",
                                   disk.dir + "/o.spt is complete and valid, only the preview was not written"}));
    EXPECT_EQ(disk.names(), std::vector<std::string>{"o.spt"});
    EXPECT_EQ(run_spt(d, {"verify", disk.dir + "/o.spt"}).code, 0);
}

TEST(HostileOutputs, AVideoOnAFullDiskNamesTheFileAndTheReason) {
    TempDir d;
    fs::create_directories(d.file("seq"));
    // Twelve key frames of noise: a 6 KB file, a 21 KB mp4.
    for (uint32_t i = 0; i < 12; ++i) noise_png(d, "seq/f." + std::to_string(10000 + i).substr(1) + ".png", 256, 256, i);
    ASSERT_EQ(run_spt(d, {"paint", d.file("seq/f.####.png"), "-o", d.file("s.spt"), "--max-strokes", "2000",
                          "--keyframe-interval", "1"}).code, 0);
    {
        // Full before it starts: the writer cannot open.
        SmallDisk disk(d.file("full"), 64);
        disk.fill(64, 0);
        EXPECT_TRUE(failed_with(run_spt(d, {"render", d.file("s.spt"), "-o", disk.dir + "/v.mp4"}), 1,
                                {disk.dir + "/v.mp4: No space left on device"}));
        EXPECT_TRUE(disk.names().empty()) << disk.names().size();
    }
    // Full half-way: OpenCV's writer drops what it cannot write without a word.
    SmallDisk disk(d.file("half"), 64);
    disk.fill(64, 8);
    EXPECT_TRUE(failed_with(run_spt(d, {"render", d.file("s.spt"), "-o", disk.dir + "/v.mp4"}), 1,
                            {disk.dir + "/v.mp4: No space left on device"}));
    EXPECT_TRUE(disk.names().empty()) << disk.names().size();
}

TEST(HostileOutputs, AWebFolderOnAFullDiskIsTakenBack) {
    TempDir d;
    const std::string in = noise_png(d, "n.png", 64, 64, 5);
    ASSERT_EQ(run_spt(d, {"paint", in, "-o", d.file("n.spt"), "--max-strokes", "40"}).code, 0);
    SmallDisk disk(d.file("disk"), 256);  // the player is about 690 KB
    EXPECT_TRUE(failed_with(run_spt(d, {"export", d.file("n.spt"), "-o", disk.dir + "/site", "--web"}), 1,
                            {"No space left on device", disk.dir + "/site was removed"}));
    EXPECT_TRUE(disk.names().empty());
    // Into a folder that was there: it stays, without what this run added.
    fs::create_directories(disk.dir + "/mine");
    write_text(disk.dir + "/mine/keep.txt", "mine");
    EXPECT_TRUE(failed_with(run_spt(d, {"export", d.file("n.spt"), "-o", disk.dir + "/mine", "--web"}), 1,
                            {"No space left on device", "the files this run added to " + disk.dir + "/mine were removed"}));
    std::vector<std::string> left;
    for (const auto& e : fs::directory_iterator(disk.dir + "/mine")) left.push_back(e.path().filename().string());
    EXPECT_EQ(left, std::vector<std::string>{"keep.txt"});
}

TEST(HostileOutputs, AnExrWithoutColourChannelsIsSaid) {
    TempDir d;
    const std::pair<std::vector<std::string>, std::string> cases[] = {
        {{"Z"}, "(channels: Z): painted as grey from Z"},
        {{"A"}, "(channels: A): painted as grey from A"},
        {{"R", "G"}, "(channels: R, G): painted as grey from R with G as alpha"},
        {{"X", "Y", "Z"}, "(channels: X, Y, Z): painted as R, G, B from X, Y, Z"},
    };
    int i = 0;
    for (const auto& [names, said] : cases) {
        const std::string in = exr(d, "c" + std::to_string(i++) + ".exr", names);
        const auto r = run_spt(d, {"paint", in, "-o", d.file("o.spt")});
        EXPECT_EQ(r.code, 0) << r.err;
        EXPECT_NE(r.err.find("warning: " + in + ": has no R, G, B channels " + said), std::string::npos) << r.err;
    }
    const auto r = run_spt(d, {"paint", exr(d, "rgb.exr", {"R", "G", "B"}), "-o", d.file("o.spt")});
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
}

TEST(HostileOutputs, ADisplayWindowOverTheLimitIsRefused) {
    TempDir d;
    const std::string in = exr(d, "dw.exr", {"R", "G", "B"}, 100000);
    EXPECT_TRUE(refused(d, {"paint", in, "-o", d.file("o.spt")}, 1,
                        {in + ": has a display window of 100000x100000, over the size limit"}, d.file("o.spt")));
}
