#pragma once

#include <string>
#include <vector>

#include "core/camera.h"
#include "core/status.h"
#include "io/dataset.h"

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
};

// One scene of an --input: a dataset scene, a plain folder of images, or a single image.
struct InputScene {
  std::string name;                  // Output folder name: the scene's or the folder's name.
  std::string camera_source;         // The file the camera came from.
  Camera camera;                     // Checked, with a positive mount height.
  std::vector<DatasetFrame> frames;  // Sorted by name; depth/truth/floor paths when available.
};

// Resolves --input (an image file, a folder of images, or a dataset root in the foundation
// layout) into scenes with their cameras: --camera if given, else --fx/--fy/--cx/--cy, else
// <scene>/camera.yaml, else <dataset>/camera.yaml (for a single image or a plain folder:
// camera.yaml beside the images, then in the parent folder), else --hfov; the pinholes from flags
// take the size of the scene's first image. The height is --camera_height if given, else the camera_height key.
// Every failure is an InvalidArgument or NotFound that names the path.
Status ResolveInput(const std::string& input, const CameraOverrides& overrides,
                    std::vector<InputScene>* scenes);

// Is the calibration for these images? Reads the scene's first frame and compares its size with
// the camera's: an InvalidArgument naming both files and both sizes when they differ, so that a
// wrong camera is a configuration error found before any work. A first frame that cannot be read
// passes here (it fails as a frame in the run), as does a later odd-sized frame.
Status CheckFirstFrameSize(const InputScene& scene);

}  // namespace corridor
