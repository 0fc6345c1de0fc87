#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/status.h"
#include "corridor_depth/dataset.h"

namespace corridor {

// How the tools find the camera when the input does not carry its own.
struct CameraOverrides {
  std::string camera_file;     // --camera: used for every scene when set.
  double camera_height = 0.0;  // --camera_height: metres, used when != 0 (checked).
  double fx = 0.0;             // --fx: with --fy, --cx, --cy, a pinhole on the command line (0 = none).
  double fy = 0.0;             // --fy, pixels (0 = same as --fx).
  double cx = -1.0;            // --cx, pixels (< 0 = image centre).
  double cy = -1.0;            // --cy, pixels (< 0 = image centre).
  double hfov_deg = 0.0;       // --hfov: pinhole from a horizontal field of view, for images without calibration (0 = none).
  std::string focal;           // --focal: "auto" = focal from two vanishing points (fallback --hfov, else 60 deg); "" = off.
};

// Which topics of a ROS bag to read (--image_topic, --camera_info_topic).
struct BagTopicOptions {
  std::string image_topic;        // "" = the bag's only sensor_msgs/Image or CompressedImage topic.
  std::string camera_info_topic;  // "" = the camera_info topic beside the image topic.
};

// What holds a scene's frames.
enum class InputKind {
  kImages,  // Image files (frames[]).
  kRosBag,  // The image messages of one topic of a ROS 1 bag (stream_path, image_topic).
  kVideo,   // A video file that OpenCV's VideoCapture reads (stream_path).
};

// One scene of an --input: a dataset scene, a plain folder of images, a single image, a ROS bag
// or a video.
struct InputScene {
  std::string name;                     // Output folder name: the scene's or the folder's name.
  std::string camera_source;            // Where the camera came from (a file, a bag topic, flags).
  Camera camera;                        // Checked, with a positive mount height.
  std::vector<DatasetFrame> frames;     // kImages: sorted by name; depth/truth/floor paths if any.
  InputKind kind = InputKind::kImages;  // What holds the frames.
  std::string stream_path;              // kRosBag, kVideo: the file.
  std::string image_topic;              // kRosBag: the topic read.
  std::string frame_id;                 // kRosBag: the CameraInfo's frame_id ("" otherwise).
  int64_t frame_count = 0;              // Frames (a video's is its container's estimate).
  double frame_period = 0.1;            // Seconds between frames without a stamp (a video's 1/fps).
  // Images with a camera from --hfov alone: each image gets a pinhole of its own size with this
  // field of view (degrees) and is read upright (EXIF orientation), as a photo viewer shows it;
  // `camera` is then the first image's. 0 = the scene's camera serves every frame, and images are
  // read as stored (a calibration is for the image as stored).
  double per_image_hfov_deg = 0;
};

// The camera of one frame of the scene: the scene's, or, with per_image_hfov_deg, a pinhole of
// the image's own size.
Camera FrameCamera(const InputScene& scene, const cv::Size& image_size);

// The field of view --focal=auto falls back to without --hfov, degrees.
constexpr double kDefaultFallbackHfovDeg = 60.0;

// Resolves --input (an image file, a folder of images, a dataset root in the foundation
// layout, a ROS 1 bag `.bag`, or a video file) into scenes with their cameras. A bag's camera is
// its CameraInfo unless --camera or the uncalibrated flags are given; a video needs --camera (or
// the uncalibrated flags). Otherwise: --camera if given, else --fx/--fy/--cx/--cy, else
// --focal=auto (a pinhole at the centre whose focal comes from the images; it replaces a
// camera.yaml), else <scene>/camera.yaml, else <dataset>/camera.yaml (for a single image or a plain folder:
// camera.yaml beside the images, then in the parent folder), else --hfov; the pinholes from flags
// take the size of the scene's first image. The height is --camera_height if given, else the camera_height key.
// Every failure is an InvalidArgument or NotFound that names the path.
Status ResolveInput(const std::string& input, const CameraOverrides& overrides,
                    std::vector<InputScene>* scenes,
                    const BagTopicOptions& bag_topics = BagTopicOptions());

// True for the file extensions read as videos (.avi, .mp4, .mkv, .mov, .webm, ...).
bool IsVideoPath(const std::string& path);

// Is the calibration for these images? Reads the scene's first frame and compares its size with
// the camera's: an InvalidArgument naming both files and both sizes when they differ, so that a
// wrong camera is a configuration error found before any work. A first frame that cannot be read
// passes here (it fails as a frame in the run), as does a later odd-sized frame.
Status CheckFirstFrameSize(const InputScene& scene);

}  // namespace corridor
