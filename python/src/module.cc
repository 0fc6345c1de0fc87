// The Python module corridor_depth: depth from one corridor image, with numpy arrays in and out.

#include "python/src/bindings.h"

PYBIND11_MODULE(corridor_depth, m) {
  m.doc() =
      "Metric depth from one image of an indoor corridor.\n\n"
      "Images are numpy arrays: uint8 (or uint16) HxWx3 in BGR order as OpenCV reads them\n"
      "(pass rgb=True for RGB), HxWx4 BGRA, or HxW grey. Depth is float32 HxW in metres, NaN\n"
      "where there is no estimate. Angles are in radians, lengths in metres.";
  m.attr("__version__") = CORRIDOR_VERSION;
  corridor::python::BindCamera(m);
  corridor::python::BindRecover(m);
  corridor::python::BindSequence(m);
  corridor::python::BindSolvers(m);
  corridor::python::BindResiduals(m);
  corridor::python::BindMetrics(m);
}
