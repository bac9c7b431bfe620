// SPEC.md 7.4: the affine matrix coding is canonical. A matrix with b = c = 0 coded with the
// axis_aligned flag 0 and the similarity flag 1 (c = 0) is axis-aligned and MUST be refused;
// libspt accepted it until the educational decoder, written from the spec, refused it. The two
// files were hand-coded by that decoder's author: the same canvas and stroke, the matrix
// once as the spec wants it and once as a similarity with c = 0.
#include <gtest/gtest.h>

#include "spt/reader.hpp"

using namespace spt;

namespace {
const std::string kDir = std::string(SPT_SOURCE_DIR) + "/tests/format/noncanonical";
}

TEST(CanonicalMatrix, AxisAlignedMatrixCodedAsASimilarityIsCorrupt) {
    auto o = Reader::open(kDir + "/affine_similarity_c0.spt");
    ASSERT_TRUE(o.ok()) << o.error().message;
    auto s = (*o)->strokes_at(0);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().code, Code::Corrupt);
    EXPECT_NE(s.error().message.find("an axis-aligned matrix coded as a similarity"), std::string::npos)
        << s.error().message;
}

TEST(CanonicalMatrix, TheSameMatrixCodedAxisAlignedDecodes) {
    auto o = Reader::open(kDir + "/affine_axis_aligned.spt");
    ASSERT_TRUE(o.ok()) << o.error().message;
    auto s = (*o)->strokes_at(0);
    ASSERT_TRUE(s.ok()) << s.error().message;
    ASSERT_EQ((*s)->size(), 1u);
}
