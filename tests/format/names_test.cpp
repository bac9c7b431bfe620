// The names libspt gives codings, fields, template kinds and error codes: tools print them
// (spt info, JSON exports), so each value has one name, from one table.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "spt/spt.hpp"

using namespace spt;

TEST(Names, EveryCodingHasItsOwn) {
    EXPECT_STREQ(coding_name(Coding::Stored), "stored");
    EXPECT_STREQ(coding_name(Coding::Range), "range");
    EXPECT_STREQ(coding_name(Coding::Replay), "replay");
    EXPECT_STREQ(coding_name(Coding(3)), "reserved");
}

TEST(Names, TemplateKindsAndFieldsAreDistinct) {
    std::set<std::string> kinds;
    for (int k = 0; k < 4; ++k) kinds.insert(template_kind_name(TemplateKind(k)));
    EXPECT_EQ(kinds, (std::set<std::string>{"bitmap", "ellipse", "rectangle", "triangle"}));
    EXPECT_STREQ(template_kind_name(TemplateKind(4)), "unknown");
    std::set<std::string> fields;
    for (size_t f = 0; f < kFieldCount; ++f) fields.insert(field_name(Field(f)));
    EXPECT_EQ(fields.size(), kFieldCount);
    EXPECT_EQ(fields.count("?"), 0u);
}
