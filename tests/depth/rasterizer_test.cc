#include "corridor_depth/rasterizer.h"

#include <cmath>

#include <gtest/gtest.h>

#include "box_truth.h"
#include "random_views.h"

namespace corridor {
namespace {

TEST(RasterizerFactoryTest, CreatesByNameAndListsValidNames) {
  std::unique_ptr<DepthRasterizer> r;
  ASSERT_TRUE(CreateRasterizer("exact", RasterizerOptions(), &r).ok());
  EXPECT_EQ(r->Name(), "exact");
  ASSERT_TRUE(CreateRasterizer("paper", RasterizerOptions(), &r).ok());
  EXPECT_EQ(r->Name(), "paper");
  const Status bad = CreateRasterizer("fancy", RasterizerOptions(), &r);
  EXPECT_EQ(bad.code(), StatusCode::kInvalidArgument);
  EXPECT_NE(bad.message().find("paper, exact"), std::string::npos) << bad.message();
}

TEST(RasterizerFactoryTest, RejectsBadOptions) {
  RasterizerOptions options;
  options.max_range = -1;
  std::unique_ptr<DepthRasterizer> r;
  EXPECT_EQ(CreateRasterizer("exact", options, &r).code(), StatusCode::kInvalidArgument);
}

TEST(RasterizerFactoryTest, GeometryChecks) {
  CorridorGeometry g;
  g.width = 2;
  g.camera_height = 0.6;
  EXPECT_TRUE(CheckGeometryForRendering(g).ok());
  g.yaw = std::nan("");
  EXPECT_FALSE(CheckGeometryForRendering(g).ok());
  g.yaw = 1.6;
  EXPECT_EQ(CheckGeometryForRendering(g).code(), StatusCode::kImplausibleGeometry);
}

// The base class's RenderNoEstimateNaN (the paper rasteriser has no pass of its own): Render's
// depths, every pixel not positive made NaN; a bad geometry's status passed on.
TEST(RasterizerTest, PaperNoEstimateNaNIsRenderWithItsZerosMarked) {
  std::unique_ptr<DepthRasterizer> r;
  ASSERT_TRUE(CreateRasterizer("paper", RasterizerOptions(), &r).ok());
  const Camera camera = testing::TestCamera();
  const CorridorGeometry g = testing::TestGeometry(0.1, 0.05, 0.2, 2.2, 2.6);
  cv::Mat plain, marked;
  ASSERT_TRUE(r->Render(g, camera, &plain).ok());
  ASSERT_TRUE(r->RenderNoEstimateNaN(g, camera, &marked).ok());
  EXPECT_GT(testing::ExpectNaNWhereNotPositive(plain, marked), 0);
  CorridorGeometry outside = g;
  outside.offset = 5;
  EXPECT_EQ(r->RenderNoEstimateNaN(outside, camera, &marked).code(),
            r->Render(outside, camera, &plain).code());
}

}  // namespace
}  // namespace corridor
