#include "synth/corridor_renderer.h"

#include <cmath>
#include <sstream>

#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

#include "synth/ray_caster.h"

namespace corridor {
namespace synth {
namespace {

Status CheckPose(const SceneOptions& o, const CameraPose& pose) {
  std::ostringstream msg;
  const double values[] = {pose.pitch, pose.yaw, pose.offset, pose.height, pose.distance, pose.roll};
  for (double v : values) {
    if (!std::isfinite(v)) return Status::InvalidArgument("camera pose has a non-finite value");
  }
  if (std::abs(pose.offset) > 0.5 * o.width - 0.05) {
    msg << "camera offset " << pose.offset << " m puts it within 5 cm of a wall (width "
        << o.width << " m)";
  } else if (!(pose.height > 0.05 && pose.height < o.ceiling_height - 0.05)) {
    msg << "camera height " << pose.height << " m is not between floor and ceiling";
  } else if (!(pose.distance >= 0 && pose.distance < o.length - 0.5)) {
    msg << "camera distance " << pose.distance << " m is not inside the corridor (length "
        << o.length << " m)";
  } else if (std::abs(pose.yaw) > 1.2 || std::abs(pose.pitch) > 1.2) {
    msg << "yaw and pitch must be within +-1.2 rad";
  } else if (std::abs(pose.roll) > 0.5) {
    msg << "roll must be within +-0.5 rad";
  } else {
    return Status::Ok();
  }
  return Status::InvalidArgument(msg.str());
}

// Shaded colour of a hit seen along `direction` (unit), in [0, 1].
cv::Vec3f Shade(const Hit& hit, const Eigen::Vector3d& direction, double distance, double falloff) {
  if (hit.emissive) return hit.albedo;
  const double lambert = std::max(0.0, -hit.normal.dot(direction));
  const double light = (0.45 + 0.55 * lambert) / (1.0 + falloff * distance * distance);
  return hit.albedo * static_cast<float>(light);
}

// The colour seen along `direction` (unnormalised: the hit's t times its norm is the distance)
// from `origin`, which met `hit`: shaded, and on a glossy floor mixed with what the mirrored ray
// meets (the floor is the plane y = 0, facing up; the mirrored ray starts on it), that share fading
// with the mirrored ray's length on a satin floor.
cv::Vec3f SampleColour(const CorridorScene& scene, const Eigen::Vector3d& origin,
                       const Eigen::Vector3d& direction, const Hit& hit) {
  const double falloff = scene.options.falloff;
  const double distance = hit.t * direction.norm();
  const cv::Vec3f shaded = Shade(hit, direction.normalized(), distance, falloff);
  const double gloss = scene.options.floor_gloss;
  const Eigen::Vector3d point = origin + hit.t * direction;
  if (!(gloss > 0) || hit.emissive || hit.normal.y() < 0.999 || std::abs(point.y()) > 1e-6) {
    return shaded;
  }
  const Eigen::Vector3d mirrored(direction.x(), -direction.y(), direction.z());
  const Hit seen = CastRay(scene, Eigen::Vector3d(point.x(), 1e-9, point.z()), mirrored);
  if (!seen.found) return shaded;
  const double mirrored_length = seen.t * mirrored.norm();
  const cv::Vec3f reflected =
      Shade(seen, mirrored.normalized(), distance + mirrored_length, falloff);
  const double reach = scene.options.floor_gloss_reach;
  const double share = reach > 0 ? gloss * std::exp(-mirrored_length / reach) : gloss;
  return shaded * static_cast<float>(1.0 - share) + reflected * static_cast<float>(share);
}

}  // namespace

Status RenderFrame(const SceneOptions& options, const Camera& camera, const CameraPose& pose,
                   Frame* frame) {
  std::string why;
  if (!options.Check(&why)) return Status::InvalidArgument("scene: " + why);
  return RenderFrame(BuildScene(options), camera, pose, frame);
}

Status RenderFrame(const CorridorScene& scene, const Camera& camera, const CameraPose& pose,
                   Frame* frame) {
  std::string why;
  if (!scene.options.Check(&why)) return Status::InvalidArgument("scene: " + why);
  if (!camera.CheckIntrinsics(&why)) return Status::InvalidArgument("camera: " + why);
  Status status = CheckPose(scene.options, pose);
  if (!status.ok()) return status;

  // Camera-from-corridor rotation (docs/geometry.md: R_x(pitch) R_y(yaw), corridor Y down; the roll
  // about the optical axis comes last), built with Eigen; the world frame here has y up, hence
  // the flip.
  const Eigen::Matrix3d camera_from_corridor =
      (Eigen::AngleAxisd(pose.roll, Eigen::Vector3d::UnitZ()) *
       Eigen::AngleAxisd(pose.pitch, Eigen::Vector3d::UnitX()) *
       Eigen::AngleAxisd(pose.yaw, Eigen::Vector3d::UnitY()))
          .toRotationMatrix();
  const Eigen::Matrix3d flip = Eigen::Vector3d(1, -1, 1).asDiagonal();
  const Eigen::Matrix3d world_from_camera = flip * camera_from_corridor.transpose();
  const Eigen::Vector3d origin(pose.offset, pose.height, pose.distance);

  const int w = camera.image_width, h = camera.image_height;
  cv::Mat color(h, w, CV_32FC3);
  frame->depth.create(h, w, CV_32F);
  const double offsets[4][2] = {{-0.25, -0.25}, {0.25, -0.25}, {-0.25, 0.25}, {0.25, 0.25}};
  for (int v = 0; v < h; ++v) {
    for (int u = 0; u < w; ++u) {
      // Unnormalised rays with camera z = 1: the hit's t is its camera-frame depth.
      const Eigen::Vector3d centre((u - camera.cx) / camera.fx, (v - camera.cy) / camera.fy, 1.0);
      const Hit hit = CastRay(scene, origin, world_from_camera * centre);
      frame->depth.at<float>(v, u) = hit.found ? static_cast<float>(hit.t) : 0.0f;
      cv::Vec3f sum(0, 0, 0);
      for (const auto& o : offsets) {
        const Eigen::Vector3d ray((u + o[0] - camera.cx) / camera.fx,
                                  (v + o[1] - camera.cy) / camera.fy, 1.0);
        const Eigen::Vector3d direction = world_from_camera * ray;
        const Hit sample = CastRay(scene, origin, direction);
        if (!sample.found) continue;
        sum += SampleColour(scene, origin, direction, sample);
      }
      color.at<cv::Vec3f>(v, u) = sum * 0.25f;
    }
  }
  if (scene.options.blur_sigma > 0) {
    cv::GaussianBlur(color, color, cv::Size(0, 0), scene.options.blur_sigma);
  }
  color.convertTo(frame->bgr, CV_8UC3, 255.0);
  if (scene.options.noise_sigma > 0) {
    // Seeded by the scene and the pose, so the same frame always gets the same noise.
    const uint64_t seed = scene.options.seed * 1000003ull +
                          static_cast<uint64_t>(std::llround(pose.distance * 1000.0));
    cv::RNG rng(seed);
    cv::Mat noise(h, w, CV_16SC3);
    rng.fill(noise, cv::RNG::NORMAL, 0, scene.options.noise_sigma);
    cv::Mat sum;
    frame->bgr.convertTo(sum, CV_16SC3);
    sum += noise;
    sum.convertTo(frame->bgr, CV_8UC3);
  }
  frame->truth.yaw = pose.yaw;
  frame->truth.pitch = pose.pitch;
  frame->truth.offset = pose.offset;
  frame->truth.width = scene.options.width;
  frame->truth.camera_height = pose.height;
  frame->truth.ceiling_height = scene.options.ceiling_height;
  return Status::Ok();
}

}  // namespace synth
}  // namespace corridor
