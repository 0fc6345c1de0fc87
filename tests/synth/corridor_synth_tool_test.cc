// The corridor_synth binary's real-buildings preset and part switches, run as a user runs them.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;

int RunSynth(const std::string& args) {
  const std::string command = std::string(CORRIDOR_BINARY_DIR) + "/tools/corridor_synth " + args +
                              " > /dev/null 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

class CorridorSynthToolTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("corridor_synth_tool_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(CorridorSynthToolTest, WritesOneRealBuildingsClass) {
  ASSERT_EQ(RunSynth("--preset=real_buildings --real_class=glass --real_scenes=2 --real_frames=2 "
                     "--width_px=96 --height_px=72 --output_dir=" +
                     dir_.string()),
            0);
  for (const char* scene : {"glass_s3400", "glass_s3407"}) {
    EXPECT_TRUE(fs::exists(dir_ / scene / "truth.yaml")) << scene;
    EXPECT_TRUE(fs::exists(dir_ / scene / "camera.yaml")) << scene;
    EXPECT_TRUE(fs::exists(dir_ / scene / "rgb" / "000001.png")) << scene;
    EXPECT_TRUE(fs::exists(dir_ / scene / "depth" / "000001.png")) << scene;
    EXPECT_FALSE(fs::exists(dir_ / scene / "rgb" / "000002.png")) << scene;
  }
  EXPECT_FALSE(fs::exists(dir_ / "glass_s3414"));
}

TEST_F(CorridorSynthToolTest, RejectsUnknownClassesAndBadCounts) {
  EXPECT_EQ(RunSynth("--preset=real_buildings --real_class=sofa --output_dir=" + dir_.string()), 2);
  EXPECT_EQ(RunSynth("--preset=real_buildings --real_class=rail --real_frames=0 --output_dir=" +
                     dir_.string()),
            2);
  EXPECT_EQ(RunSynth("--preset=single --furniture=1.5 --output_dir=" + dir_.string()), 2);
}

TEST_F(CorridorSynthToolTest, PartSwitchesAndRollOnASingleFrame) {
  EXPECT_EQ(RunSynth("--preset=single --handrails --chair_rails --wainscot --furniture=0.5 --runner "
                     "--floor_stripes --carpet --glass_walls --window_bands --pillars --roll=0.03 "
                     "--width_px=96 --height_px=72 --output_dir=" +
                     dir_.string()),
            0);
  EXPECT_TRUE(fs::exists(dir_ / "corridor" / "rgb" / "000000.png"));
  EXPECT_EQ(RunSynth("--preset=single --roll=0.9 --width_px=96 --height_px=72 --output_dir=" +
                     dir_.string()),
            2);
  // --hfov_deg is the old name of --hfov: still taken, and checked like it.
  EXPECT_EQ(RunSynth("--preset=single --hfov_deg=70 --width_px=96 --height_px=72 --output_dir=" +
                     dir_.string()),
            0);
  EXPECT_EQ(RunSynth("--preset=single --hfov_deg=175 --output_dir=" + dir_.string()), 2);
  EXPECT_EQ(RunSynth("--preset=single --hfov=175 --output_dir=" + dir_.string()), 2);
}

}  // namespace
