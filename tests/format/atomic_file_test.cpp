// spt::AtomicFile and the Writer over it: outputs nobody can redirect, nothing left behind (issue 20).
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "spt/atomic_file.hpp"
#include "spt/spt.hpp"
#include "format/test_dir.hpp"

using namespace spt;
using namespace spt::testing;
namespace fs = std::filesystem;

namespace {

Status write_one_frame(const std::string& path, const StreamInfo& info) {
    auto w = Writer::create(path, info);
    if (!w) return w.error();
    Frame f;
    if (Status s = (*w)->append(f); !s) return s;
    return (*w)->finish();
}

}  // namespace
// The old writer opened "<path>.partial" with fopen: a symlink planted there was followed and
// its target overwritten with .spt bytes.
TEST(AtomicFile, NeverWritesThroughASymlinkAtTheOldTemporaryName) {
    TestDir d;
    { std::ofstream(d / "victim.txt") << "victim"; }
    fs::create_symlink("victim.txt", d / "o.spt.partial");
    ASSERT_TRUE(write_one_frame(d / "o.spt", small_info()).ok());
    EXPECT_EQ(slurp(d / "victim.txt"), "victim");
    EXPECT_FALSE(fs::is_symlink(d / "o.spt"));
    EXPECT_TRUE(Reader::open(d / "o.spt").ok());
}

// A symlink at the final name is replaced by the file, never written through.
TEST(AtomicFile, ReplacesASymlinkAtTheFinalNameWithoutFollowingIt) {
    TestDir d;
    { std::ofstream(d / "victim.txt") << "victim"; }
    fs::create_symlink("victim.txt", d / "o.spt");
    fs::create_symlink("nowhere", d / "dangling.spt");
    ASSERT_TRUE(write_one_frame(d / "o.spt", small_info()).ok());
    ASSERT_TRUE(write_one_frame(d / "dangling.spt", small_info()).ok());
    EXPECT_EQ(slurp(d / "victim.txt"), "victim");
    EXPECT_FALSE(fs::is_symlink(d / "o.spt"));
    EXPECT_FALSE(fs::is_symlink(d / "dangling.spt"));
    EXPECT_FALSE(fs::exists(d / "nowhere"));
    EXPECT_EQ(d.names(), (std::vector<std::string>{"dangling.spt", "o.spt", "victim.txt"}));
}

// On Linux the temporary has no name at all: the folder shows nothing until commit, and nothing
// after discard (or after a crash, which discards the same way).
TEST(AtomicFile, IsUnnamedUntilCommittedAndLeavesNothingWhenDiscarded) {
    TestDir d;
    {
        auto f = AtomicFile::create(d / "a.bin");
        ASSERT_TRUE(f.ok()) << f.error().message;
#ifdef __linux__
        EXPECT_TRUE(f->unnamed()) << "O_TMPFILE is expected on Linux's usual file systems";
#endif
        std::fputs("half", f->stream());
        std::fflush(f->stream());
        if (f->unnamed()) EXPECT_TRUE(d.names().empty());
        f->discard();
        EXPECT_TRUE(d.names().empty());
        auto g = AtomicFile::create(d / "b.bin");
        ASSERT_TRUE(g.ok());
        std::fputs("whole", g->stream());
        ASSERT_TRUE(g->commit().ok());
    }  // a destroyed, uncommitted AtomicFile is discarded too
    { auto h = AtomicFile::create(d / "c.bin"); ASSERT_TRUE(h.ok()); std::fputs("lost", h->stream()); }
    EXPECT_EQ(d.names(), std::vector<std::string>{"b.bin"});
    EXPECT_EQ(slurp(d / "b.bin"), "whole");
}

TEST(AtomicFile, ReplacesAnExistingFileAtomically) {
    TestDir d;
    { std::ofstream(d / "a.bin") << "old"; }
    ASSERT_TRUE(write_file_atomic(d / "a.bin", "new", 3).ok());
    EXPECT_EQ(slurp(d / "a.bin"), "new");
    EXPECT_EQ(d.names(), std::vector<std::string>{"a.bin"});
}

TEST(AtomicFile, RefusesFoldersMissingFoldersAndReadOnlyFolders) {
    TestDir d;
    fs::create_directories(d / "sub");
    auto a = AtomicFile::create(d / "sub");
    ASSERT_FALSE(a.ok());
    EXPECT_NE(a.error().message.find("is a folder"), std::string::npos) << a.error().message;
    auto b = AtomicFile::create(d / "missing/x.spt");
    ASSERT_FALSE(b.ok());
    EXPECT_NE(b.error().message.find("missing/x.spt"), std::string::npos) << b.error().message;
    EXPECT_FALSE(check_output_path(d / "missing/x.spt").ok());
    EXPECT_TRUE(check_output_path(d / "fine.spt").ok());
    EXPECT_FALSE(fs::exists(d / "fine.spt")) << "a check leaves nothing";
    if (::geteuid() != 0) {  // root writes anywhere
        fs::create_directories(d / "ro");
        ::chmod((d / "ro").c_str(), 0555);
        EXPECT_FALSE(AtomicFile::create(d / "ro/x.spt").ok());
        ::chmod((d / "ro").c_str(), 0755);
    }
}

TEST(AtomicFile, WriterAbortLeavesNothing) {
    TestDir d;
    auto w = Writer::create(d / "o.spt", small_info());
    ASSERT_TRUE(w.ok());
    Frame f;
    ASSERT_TRUE((*w)->append(f).ok());
    (*w)->abort();
    EXPECT_TRUE(d.names().empty());
}

// Where O_TMPFILE is missing: an exclusively created random name beside the destination, which
// a symlink planted at any name cannot redirect, renamed into place; nothing left on discard.
TEST(AtomicFile, NamedFallbackIsExclusiveAndCleansUp) {
    TestDir d;
    { std::ofstream(d / "victim.txt") << "victim"; }
    fs::create_symlink("victim.txt", d / "o.bin");
    auto f = AtomicFile::create(d / "o.bin", false);
    ASSERT_TRUE(f.ok()) << f.error().message;
    EXPECT_FALSE(f->unnamed());
    const std::vector<std::string> during = d.names();
    ASSERT_EQ(during.size(), 3u);
    const std::string temp = during[0];  // ".o.bin.XXXXXXXXXXXX.tmp" sorts first
    EXPECT_EQ(temp.rfind(".o.bin.", 0), 0u) << temp;
    EXPECT_EQ(temp.size(), std::string(".o.bin.").size() + 12 + 4) << temp;
    EXPECT_FALSE(fs::is_symlink(d.path / temp));
    std::fputs("new", f->stream());
    ASSERT_TRUE(f->commit().ok());
    EXPECT_EQ(slurp(d / "victim.txt"), "victim");
    EXPECT_EQ(slurp(d / "o.bin"), "new");
    EXPECT_FALSE(fs::is_symlink(d / "o.bin"));
    EXPECT_EQ(d.names(), (std::vector<std::string>{"o.bin", "victim.txt"}));
    auto g = AtomicFile::create(d / "p.bin", false);
    ASSERT_TRUE(g.ok());
    g->discard();
    EXPECT_EQ(d.names(), (std::vector<std::string>{"o.bin", "victim.txt"}));
}
