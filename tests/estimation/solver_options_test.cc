#include "corridor_depth/solver_options.h"

#include <gtest/gtest.h>

namespace corridor {
namespace {

TEST(SolverOptionsTest, DefaultsAreValid) {
  std::string why;
  EXPECT_TRUE(SolverOptions().Check(&why)) << why;
}

TEST(SolverOptionsTest, RejectsEmptyInvertedAndZeroStepRanges) {
  std::string why;
  GridSearchOptions grid;
  grid.pitch_min = 0.3;
  grid.pitch_max = -0.3;
  EXPECT_FALSE(grid.Check(&why));
  EXPECT_NE(why.find("inverted"), std::string::npos) << why;
  grid = GridSearchOptions();
  grid.width_step = 0;
  EXPECT_FALSE(grid.Check(&why));
  EXPECT_NE(why.find("step"), std::string::npos) << why;
  grid = GridSearchOptions();
  grid.offset_min = grid.offset_max;
  EXPECT_FALSE(grid.Check(&why));
}

TEST(SolverOptionsTest, RejectsUnknownLoss) {
  SolverOptions options;
  options.loss = "tukey";
  std::string why;
  EXPECT_FALSE(options.Check(&why));
  EXPECT_NE(why.find("huber"), std::string::npos) << why;
}

TEST(SolverOptionsTest, ParsesChains) {
  std::vector<SolverType> chain;
  std::string why;
  ASSERT_TRUE(ParseSolverChain("closed_form+lm", &chain, &why)) << why;
  ASSERT_EQ(chain.size(), 2u);
  EXPECT_EQ(chain[0], SolverType::kClosedForm);
  EXPECT_EQ(chain[1], SolverType::kLevenbergMarquardt);
  EXPECT_FALSE(ParseSolverChain("closed_form+foo", &chain, &why));
  EXPECT_NE(why.find("foo"), std::string::npos);
}

TEST(SolverOptionsTest, NamesRoundTrip) {
  for (SolverType t : {SolverType::kGridSearch, SolverType::kClosedForm,
                       SolverType::kLevenbergMarquardt, SolverType::kJoint}) {
    SolverType back;
    ASSERT_TRUE(StringToSolverType(SolverTypeToString(t), &back));
    EXPECT_EQ(back, t);
  }
}

}  // namespace
}  // namespace corridor
