// The farm library linked alone (with only what its own CMake target brings: the plan model,
// libspt and the JSON layer): this executable would not link if the farm needed the planner,
// the painters or an image library. It also runs the farm on a plan it writes itself.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "farm/farm_job.hpp"
#include "plan/plan.hpp"

namespace fs = std::filesystem;

TEST(FarmAlone, StatusOfAMissingPlanNamesIt) {
    const std::string path = (fs::temp_directory_path() / "spt-farm-alone-none.plan.json").string();
    fs::remove(path);
    auto st = spt::farm::farm_status(path);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().message.find(path), std::string::npos) << st.error().message;
}

TEST(FarmAlone, AWrittenPlanReadsBackAndIsNotYetSubmitted) {
    const fs::path dir = fs::temp_directory_path() / "spt-farm-alone";
    fs::remove_all(dir);
    fs::create_directories(dir);
    spt::plan::Plan p;
    p.input = (dir / "f.####.png").string();
    p.first = 0;
    p.last = 9;
    p.width = 4;
    p.height = 4;
    p.fps = "24/1";
    p.cuts = {0};
    p.cut_scan = "full";
    for (auto [a, b] : spt::plan::split_shot(0, 9, 100, 5)) {
        spt::plan::Shot s;
        s.index = p.shots.size();
        s.first = a;
        s.last = b;
        s.seed = 1 + s.index;
        s.starts_at_cut = a == 0;
        s.key_frames = {a};
        p.shots.push_back(s);
    }
    p.id = spt::plan::compute_id(p);
    const std::string path = (dir / "a.plan.json").string();
    ASSERT_TRUE(spt::plan::write_plan(p, path).ok());
    auto back = spt::plan::read_plan(path);
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_EQ(back->id, p.id);
    EXPECT_EQ(back->shots.size(), 2u);
    // The farm reads the plan (through the plan model) and then finds no state folder.
    auto st = spt::farm::farm_status(path);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().message.find("not submitted"), std::string::npos) << st.error().message;
}
