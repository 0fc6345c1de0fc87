#include "io/file_util.h"

#include <filesystem>

#include <gtest/gtest.h>

#include "tests/io/test_dir.h"

namespace corridor {
namespace {

using testing_util::Contains;
using testing_util::ReadAll;
using testing_util::TestDir;

TEST(FileUtilTest, ReadsBinaryContentExactly) {
  TestDir dir;
  const std::string bytes("a\0b\xff\n", 5);
  const std::string path = dir.Write("x.bin", bytes);
  std::string read;
  ASSERT_TRUE(ReadFileToString(path, &read).ok());
  EXPECT_EQ(read, bytes);
}

TEST(FileUtilTest, EmptyFileReadsAsEmpty) {
  TestDir dir;
  std::string read = "junk";
  ASSERT_TRUE(ReadFileToString(dir.Write("empty", ""), &read).ok());
  EXPECT_TRUE(read.empty());
}

TEST(FileUtilTest, MissingFileIsNotFoundAndNamed) {
  TestDir dir;
  const std::string path = dir.Path("nope.txt");
  std::string read;
  const Status status = ReadFileToString(path, &read);
  EXPECT_EQ(status.code(), StatusCode::kNotFound);
  EXPECT_TRUE(Contains(status.message(), path)) << status.message();
}

TEST(FileUtilTest, FolderIsNotAFile) {
  TestDir dir;
  std::string read;
  const Status status = ReadFileToString(dir.root().string(), &read);
  EXPECT_EQ(status.code(), StatusCode::kInvalidArgument);
  EXPECT_TRUE(Contains(status.message(), "folder")) << status.message();
}

TEST(FileUtilTest, AtomicWriteUsesHiddenSiblingWithSameExtension) {
  TestDir dir;
  const std::string path = dir.Path("a/b/name.png");
  std::string tmp;
  ASSERT_TRUE(PrepareAtomicWrite(path, &tmp).ok());
  EXPECT_TRUE(std::filesystem::is_directory(dir.Path("a/b")));  // Parents were created.
  const std::filesystem::path t(tmp);
  EXPECT_EQ(t.parent_path(), std::filesystem::path(path).parent_path());
  EXPECT_EQ(t.extension(), ".png");
  EXPECT_EQ(t.filename().string().rfind(".name.tmp-", 0), 0u) << tmp;
  std::string other;
  ASSERT_TRUE(PrepareAtomicWrite(path, &other).ok());
  EXPECT_NE(tmp, other);  // Two writers in one process never share a temporary.

  dir.Write("a/b/" + t.filename().string(), "new");
  dir.Write("a/b/name.png", "old");
  ASSERT_TRUE(FinishAtomicWrite(tmp, path).ok());
  EXPECT_EQ(ReadAll(path), "new");
  EXPECT_FALSE(std::filesystem::exists(tmp));
}

TEST(FileUtilTest, FailedRenameNamesTheTarget) {
  TestDir dir;
  const std::string path = dir.Path("target.txt");
  const Status status = FinishAtomicWrite(dir.Path("missing.tmp"), path);
  EXPECT_EQ(status.code(), StatusCode::kIoError);
  EXPECT_TRUE(Contains(status.message(), path)) << status.message();
}

TEST(FileUtilTest, ParentBlockedByAFile) {
  TestDir dir;
  dir.Write("blocker", "x");
  std::string tmp;
  const Status status = PrepareAtomicWrite(dir.Path("blocker/name.png"), &tmp);
  EXPECT_EQ(status.code(), StatusCode::kIoError);
  EXPECT_TRUE(Contains(status.message(), "blocker")) << status.message();
}

TEST(FileUtilTest, LowerExtension) {
  EXPECT_EQ(LowerExtension("a/B.PNG"), ".png");
  EXPECT_EQ(LowerExtension("x.tar.Gz"), ".gz");
  EXPECT_EQ(LowerExtension("dir.d/noext"), "");
}

}  // namespace
}  // namespace corridor
