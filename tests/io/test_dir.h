#pragma once

// A fresh, empty folder per test under ::testing::TempDir(), removed when the test ends, plus
// small helpers to write raw files into it.

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

namespace corridor {
namespace testing_util {

class TestDir {
 public:
  TestDir() {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string name = std::string("corridor_io_") + info->test_suite_name() + "_" +
                             info->name() + "_" + std::to_string(::getpid());
    root_ = std::filesystem::path(::testing::TempDir()) / name;
    std::filesystem::remove_all(root_);
    std::filesystem::create_directories(root_);
  }
  ~TestDir() {
    std::error_code ec;
    std::filesystem::remove_all(root_, ec);
  }
  TestDir(const TestDir&) = delete;
  TestDir& operator=(const TestDir&) = delete;

  // <root>/<relative>, as a string.
  std::string Path(const std::string& relative) const { return (root_ / relative).string(); }
  const std::filesystem::path& root() const { return root_; }

  // Writes raw bytes to <root>/<relative>, creating folders; returns the full path.
  std::string Write(const std::string& relative, const std::string& bytes) const {
    const std::filesystem::path p = root_ / relative;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream out(p, std::ios::binary);
    out << bytes;
    return p.string();
  }

 private:
  std::filesystem::path root_;
};

// The whole content of a file ("" when missing).
inline std::string ReadAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// True when `text` contains `part`, for readable EXPECTs on messages.
inline bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace testing_util
}  // namespace corridor
