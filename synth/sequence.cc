#include "synth/sequence.h"

#include <cmath>
#include <random>

namespace corridor {
namespace synth {

std::vector<CameraPose> MakeSequence(const SequenceOptions& o) {
  std::mt19937 engine(o.seed);
  const auto phase = [&] { return 2.0 * M_PI * (engine() / 4294967296.0); };
  const double p_yaw = phase(), p_pitch = phase(), p_offset = phase();
  std::vector<CameraPose> poses;
  for (int i = 0; i < o.frames; ++i) {
    CameraPose pose = o.base;
    pose.distance = o.base.distance + i * o.step;
    pose.yaw += o.yaw_amplitude * std::sin(0.45 * i + p_yaw);
    pose.pitch += o.pitch_amplitude * std::sin(1.3 * i + p_pitch);
    pose.offset += o.offset_amplitude * std::sin(0.3 * i + p_offset);
    poses.push_back(pose);
  }
  return poses;
}

}  // namespace synth
}  // namespace corridor
