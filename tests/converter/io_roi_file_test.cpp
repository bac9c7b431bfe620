// The --roi-file reader shared by `spt paint` on stills and the video encoder.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "io/roi_file.hpp"

using namespace spt::io;

namespace {

// The error message of a document that must be refused ("" when it was accepted).
std::string refusal(const std::string& doc) {
    auto r = parse_roi_json(doc, "r.json");
    return r.ok() ? std::string() : r.error().message;
}

}  // namespace

TEST(IoRoiFile, ParsesEveryFrameSpelling) {
    auto r = parse_roi_json(R"({"rois":[{"frames":"10-40","x":5,"y":6,"w":70,"h":80},{"frames":3,"x":0,"y":0,"w":1,"h":1},
        {"x":1,"y":2,"w":3,"h":4},{"x":1,"y":2,"w":3,"h":4,"frames":[0,7]},{"x":1,"y":2,"w":3,"h":4,"frames":"9"}]})");
    ASSERT_TRUE(r.ok()) << r.error().message;
    ASSERT_EQ(r->size(), 5u);
    EXPECT_EQ((*r)[0].first_frame, 10u);
    EXPECT_EQ((*r)[0].last_frame, 40u);
    EXPECT_EQ((*r)[0].x, 5);
    EXPECT_EQ((*r)[0].y, 6);
    EXPECT_EQ((*r)[0].w, 70);
    EXPECT_EQ((*r)[0].h, 80);
    EXPECT_EQ((*r)[1].first_frame, 3u);
    EXPECT_EQ((*r)[1].last_frame, 3u);
    EXPECT_EQ((*r)[2].first_frame, 0u) << "no \"frames\": all frames";
    EXPECT_EQ((*r)[2].last_frame, RoiRange::kAllFrames);
    EXPECT_EQ((*r)[3].first_frame, 0u);
    EXPECT_EQ((*r)[3].last_frame, 7u);
    EXPECT_EQ((*r)[4].first_frame, 9u);
    EXPECT_EQ((*r)[4].last_frame, 9u);
    auto none = parse_roi_json(R"({"rois":[]})");
    ASSERT_TRUE(none.ok());
    EXPECT_TRUE(none->empty());
}

TEST(IoRoiFile, ErrorsNameTheFileAndTheElement) {
    const std::string bad_frames = refusal(R"({"rois":[{"x":1,"y":1,"w":1,"h":1},{"frames":"x","x":5,"y":1,"w":1,"h":1}]})");
    EXPECT_NE(bad_frames.find("r.json"), std::string::npos) << bad_frames;
    EXPECT_NE(bad_frames.find("rois[1]"), std::string::npos) << bad_frames;
    EXPECT_NE(bad_frames.find("\"frames\""), std::string::npos) << bad_frames;
    const std::string no_h = refusal(R"({"rois":[{"x":1,"y":1,"w":1}]})");
    EXPECT_NE(no_h.find("rois[0]"), std::string::npos) << no_h;
    EXPECT_NE(no_h.find("\"h\""), std::string::npos) << no_h;
    const std::string truncated = refusal(R"({"rois":[)");
    EXPECT_NE(truncated.find("r.json"), std::string::npos) << truncated;
    EXPECT_NE(refusal("{\"rois\":{}}").find("\"rois\" array"), std::string::npos);
}

TEST(IoRoiFile, RefusesWhatTheSchemaForbids) {
    for (const char* doc : {
             R"([])",                                                     // not an object
             R"({"rois":[1]})",                                           // element not an object
             R"({"rois":[{"x":5,"y":6,"w":0,"h":20}]})",                  // empty rectangle
             R"({"rois":[{"x":-1,"y":6,"w":1,"h":20}]})",                 // negative corner
             R"({"rois":[{"x":1.5,"y":6,"w":1,"h":20}]})",                // not an integer
             R"({"rois":[{"x":"1","y":6,"w":1,"h":20}]})",                // not a number
             R"({"rois":[{"x":1,"y":6,"w":16777217,"h":20}]})",           // too large
             R"({"rois":[{"x":1,"y":1,"w":1,"h":1,"frames":"5-3"}]})",    // reversed range
             R"({"rois":[{"x":1,"y":1,"w":1,"h":1,"frames":"-5"}]})",     // negative frame
             R"({"rois":[{"x":1,"y":1,"w":1,"h":1,"frames":"1-"}]})",     // half a range
             R"({"rois":[{"x":1,"y":1,"w":1,"h":1,"frames":[3,2]}]})",    // reversed range
             R"({"rois":[{"x":1,"y":1,"w":1,"h":1,"frames":[1]}]})",      // one bound
             R"({"rois":[{"x":1,"y":1,"w":1,"h":1,"frames":-1}]})",       // negative frame
             R"({"rois":[{"x":1,"y":1,"w":1,"h":1,"frames":4294967295}]})",  // reserved for "all"
             R"({"rois":[{"x":1,"x":2,"y":1,"w":1,"h":1}]})",             // duplicate key
             R"({"rois":[]} x)",                                          // trailing text
         })
        EXPECT_NE(refusal(doc), "") << doc;
}

TEST(IoRoiFile, ReadsAFile) {
    const auto dir = std::filesystem::temp_directory_path() / ("spt_roi_file_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    const auto path = (dir / "rois.json").string();
    std::ofstream(path) << R"({"rois":[{"frames":"12-14","x":8,"y":8,"w":20,"h":16}]})";
    auto r = read_roi_file(path);
    ASSERT_TRUE(r.ok()) << r.error().message;
    ASSERT_EQ(r->size(), 1u);
    EXPECT_EQ((*r)[0].last_frame, 14u);
    auto missing = read_roi_file((dir / "none.json").string());
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("none.json"), std::string::npos);
    std::filesystem::remove_all(dir);
}
