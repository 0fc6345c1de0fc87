// Sequence: frames of one camera fed in order, the junctions tracked and the previous frame's
// geometry held, as the tools run videos and bags.

#include <memory>
#include <mutex>

#include "corridor_depth/depth_sequence.h"
#include "python/src/bindings.h"
#include "python/src/common.h"
#include "python/src/options.h"
#include "python/src/result.h"

namespace corridor {
namespace python {
namespace {

class PySequence {
 public:
  explicit PySequence(const py::kwargs& kwargs) {
    const RecoverDepthOptions options = OptionsFromKwargs(kwargs, &camera_height_);
    ThrowIfError(DepthSequence::Create(options, &sequence_));
  }

  PyResult Process(const py::handle& image, const Camera& camera, bool rgb) {
    const Camera with_height = WithHeight(camera, camera_height_);
    const ImageInput input = ImageFromArray(image, rgb);
    RecoverDepthResult result;
    {
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(mutex_);  // Frames in order, one at a time.
      sequence_->Process(input.mat, with_height, &result);
    }
    return MakeResult(std::move(result), input.mat.rows, input.mat.cols);
  }

  void Reset() {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(mutex_);
    sequence_->Reset();
  }

 private:
  py::object camera_height_;
  std::unique_ptr<DepthSequence> sequence_;
  std::mutex mutex_;
};

}  // namespace

void BindSequence(py::module_& m) {
  py::class_<PySequence>(m, "Sequence",
                         "Frames of one camera in order: each frame's junctions are sought near "
                         "the previous frame's, and its geometry stands in where a frame's own "
                         "is missing or implausible. Keywords as recover_depth's; camera_height "
                         "overrides the cameras'.")
      .def(py::init<const py::kwargs&>())
      .def("process", &PySequence::Process, py::arg("image"), py::arg("camera"), py::kw_only(),
           py::arg("rgb") = false, "The next frame's Result (as recover_depth's).")
      .def("reset", &PySequence::Reset, "Forget the previous frames (a new sequence).");
}

}  // namespace python
}  // namespace corridor
