#include "io/file_util.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>

namespace corridor {
namespace {

namespace fs = std::filesystem;

std::atomic<unsigned> g_tmp_counter{0};  // Makes temporary names unique within the process.

}  // namespace

Status ReadFileToString(const std::string& path, std::string* bytes) {
  bytes->clear();
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (!fs::exists(st)) return Status::NotFound(path + ": no such file");
  if (fs::is_directory(st)) return Status::InvalidArgument(path + ": is a folder, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status::IoError(path + ": cannot open for reading");
  bytes->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (in.bad()) return Status::IoError(path + ": read failed");
  return Status::Ok();
}

Status PrepareAtomicWrite(const std::string& path, std::string* tmp_path) {
  const fs::path target(path);
  if (!target.has_filename()) return Status::InvalidArgument(path + ": not a file name");
  const fs::path parent = target.parent_path();
  std::error_code ec;
  if (!parent.empty()) {
    fs::create_directories(parent, ec);
    if (ec || !fs::is_directory(parent)) {
      return Status::IoError(path + ": cannot create folder " + parent.string() + ": " +
                             (ec ? ec.message() : std::string("a file is in the way")));
    }
  }
  const std::string name = "." + target.stem().string() + ".tmp-" + std::to_string(::getpid()) +
                           "-" + std::to_string(g_tmp_counter++) + target.extension().string();
  *tmp_path = (parent / name).string();
  return Status::Ok();
}

Status FinishAtomicWrite(const std::string& tmp_path, const std::string& path) {
  std::error_code ec;
  fs::rename(tmp_path, path, ec);
  if (!ec) return Status::Ok();
  std::error_code ignored;
  fs::remove(tmp_path, ignored);
  return Status::IoError(path + ": cannot rename " + tmp_path + " to it: " + ec.message());
}

std::string LowerExtension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace corridor
