#include "io/yaml_util.h"

#include <cmath>

#include <gtest/gtest.h>

#include "tests/io/test_dir.h"

namespace corridor {
namespace {

using testing_util::Contains;
using testing_util::TestDir;

TEST(YamlUtilTest, LoadsMap) {
  TestDir dir;
  YAML::Node root;
  ASSERT_TRUE(LoadYamlMap(dir.Write("a.yaml", "a: 1\n"), &root).ok());
  EXPECT_EQ(root["a"].as<int>(), 1);
}

TEST(YamlUtilTest, LoadErrorsNameTheFile) {
  TestDir dir;
  YAML::Node root;
  const std::string missing = dir.Path("missing.yaml");
  Status status = LoadYamlMap(missing, &root);
  EXPECT_EQ(status.code(), StatusCode::kNotFound);
  EXPECT_TRUE(Contains(status.message(), missing));

  const std::string empty = dir.Write("empty.yaml", "");
  status = LoadYamlMap(empty, &root);
  EXPECT_FALSE(status.ok());
  EXPECT_TRUE(Contains(status.message(), empty) && Contains(status.message(), "empty"))
      << status.message();

  const std::string list = dir.Write("list.yaml", "- 1\n- 2\n");
  status = LoadYamlMap(list, &root);
  EXPECT_TRUE(Contains(status.message(), list) && Contains(status.message(), "not a YAML map"))
      << status.message();
}

TEST(YamlUtilTest, SyntaxErrorCarriesLine) {
  TestDir dir;
  // Line 3 is indented as if it continued the scalar of line 2, then has a second ':'.
  const std::string path = dir.Write("bad.yaml", "a: 1\nb: 2\n  c: x\n");
  YAML::Node root;
  const Status status = LoadYamlMap(path, &root);
  EXPECT_EQ(status.code(), StatusCode::kInvalidArgument);
  EXPECT_TRUE(Contains(status.message(), path)) << status.message();
  EXPECT_TRUE(Contains(status.message(), "syntax error at line 3,")) << status.message();
}

TEST(YamlUtilTest, GettersNameTheKeyPath) {
  TestDir dir;
  YAML::Node root;
  const std::string path = dir.Write("v.yaml", "n: 2.5\ni: 640\nf: 640.5\ns: abc\nl: [1]\n");
  ASSERT_TRUE(LoadYamlMap(path, &root).ok());
  const YamlContext ctx{path, "outer"};

  double d = 0;
  ASSERT_TRUE(GetYamlDouble(root, "n", ctx, true, &d).ok());
  EXPECT_EQ(d, 2.5);
  int i = 0;
  ASSERT_TRUE(GetYamlInt(root, "i", ctx, true, &i).ok());
  EXPECT_EQ(i, 640);
  std::string s;
  ASSERT_TRUE(GetYamlString(root, "s", ctx, true, &s).ok());
  EXPECT_EQ(s, "abc");

  Status status = GetYamlDouble(root, "absent", ctx, true, &d);
  EXPECT_TRUE(Contains(status.message(), path + ": missing key 'outer.absent'"))
      << status.message();
  d = 7;
  EXPECT_TRUE(GetYamlDouble(root, "absent", ctx, false, &d).ok());
  EXPECT_EQ(d, 7);  // Optional and absent: untouched.

  status = GetYamlDouble(root, "s", ctx, true, &d);
  EXPECT_TRUE(Contains(status.message(), "'outer.s' is not a number: 'abc'")) << status.message();
  status = GetYamlInt(root, "f", ctx, true, &i);
  EXPECT_TRUE(Contains(status.message(), "'outer.f' is not an integer")) << status.message();
  status = GetYamlString(root, "l", ctx, true, &s);
  EXPECT_TRUE(Contains(status.message(), "'outer.l' is not a string: a list"))
      << status.message();
  status = GetYamlDouble(root["n"], "x", ctx, true, &d);  // A scalar, not a map.
  EXPECT_TRUE(Contains(status.message(), "'outer' is not a map")) << status.message();
}

TEST(YamlUtilTest, SpecialFloatsParse) {
  TestDir dir;
  YAML::Node root;
  ASSERT_TRUE(LoadYamlMap(dir.Write("nan.yaml", "a: .nan\nb: .inf\n"), &root).ok());
  const YamlContext ctx{"nan.yaml", ""};
  double a = 0, b = 0;
  ASSERT_TRUE(GetYamlDouble(root, "a", ctx, true, &a).ok());
  ASSERT_TRUE(GetYamlDouble(root, "b", ctx, true, &b).ok());
  EXPECT_TRUE(std::isnan(a));
  EXPECT_TRUE(std::isinf(b));
}

}  // namespace
}  // namespace corridor
