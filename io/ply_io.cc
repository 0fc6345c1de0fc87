#include "corridor_depth/ply_io.h"

#include <cstring>

#include "corridor_depth/image_io.h"

namespace corridor {
namespace {

// Appends a value's bytes in little-endian order, whatever the host's.
template <typename T>
void PutLittleEndian(T value, std::string* out) {
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  const uint16_t probe = 1;
  const bool little = *reinterpret_cast<const unsigned char*>(&probe) == 1;
  for (size_t i = 0; i < sizeof(T); ++i) {
    out->push_back(static_cast<char>(bytes[little ? i : sizeof(T) - 1 - i]));
  }
}

}  // namespace

Status WritePlyAtomic(const std::string& path, const PointCloud& cloud) {
  if (cloud.xyz.size() % 3 != 0 || cloud.rgb.size() != cloud.xyz.size()) {
    return Status::InvalidArgument(path + ": point cloud has " + std::to_string(cloud.xyz.size()) +
                                   " coordinates and " + std::to_string(cloud.rgb.size()) +
                                   " colour values");
  }
  const size_t n = cloud.size();
  std::string bytes =
      "ply\nformat binary_little_endian 1.0\ncomment corridor-depth: camera frame "
      "(x right, y down, z forward), metres\nelement vertex " +
      std::to_string(n) +
      "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\n"
      "property uchar green\nproperty uchar blue\nend_header\n";
  bytes.reserve(bytes.size() + n * 15);
  for (size_t i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) PutLittleEndian(cloud.xyz[3 * i + k], &bytes);
    for (int k = 0; k < 3; ++k) bytes.push_back(static_cast<char>(cloud.rgb[3 * i + k]));
  }
  return WriteTextAtomic(path, bytes);  // Binary-safe: the bytes go out as they are.
}

}  // namespace corridor
