#include "corridor_depth/rasterizer.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace corridor
