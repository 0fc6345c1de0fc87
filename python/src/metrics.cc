// DepthMetrics and depth_metrics: the evaluation's metrics on numpy depth images.

#include <limits>

#include "corridor_depth/depth_metrics.h"
#include "python/src/bindings.h"
#include "python/src/common.h"

namespace corridor {
namespace python {
namespace {

// float metres (NaN or 0 = none) or uint16 millimetres (0 = none) as CV_32F metres, 0 = none.
cv::Mat MetresFrom(const py::handle& depth, const char* what) {
  if (!py::isinstance<py::array>(depth)) {
    throw py::value_error(std::string(what) + " must be a numpy array");
  }
  const py::array a = py::reinterpret_borrow<py::array>(depth);
  if (a.ndim() != 2) throw py::value_error(std::string(what) + " must be HxW");
  const int rows = static_cast<int>(a.shape(0)), cols = static_cast<int>(a.shape(1));
  cv::Mat out(rows, cols, CV_32FC1);
  if (a.dtype().is(py::dtype::of<uint16_t>())) {
    const auto mm = py::array_t<uint16_t, py::array::c_style>::ensure(depth);
    cv::Mat(rows, cols, CV_16UC1, const_cast<uint16_t*>(mm.data())).convertTo(out, CV_32F, 1e-3);
    return out;
  }
  const auto m = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(depth);
  if (!m) throw py::value_error(std::string(what) + " must hold numbers");
  cv::Mat(rows, cols, CV_32FC1, const_cast<float*>(m.data())).copyTo(out);
  return out;
}

}  // namespace

void BindMetrics(py::module_& m) {
  py::class_<DepthMetrics>(m, "DepthMetrics", "Depth metrics of geometry.md, section 7.")
      .def_readonly("abs_rel", &DepthMetrics::abs_rel)
      .def_readonly("sq_rel", &DepthMetrics::sq_rel)
      .def_readonly("rmse", &DepthMetrics::rmse)
      .def_readonly("rmse_log", &DepthMetrics::rmse_log)
      .def_readonly("rmse_log10", &DepthMetrics::rmse_log10)
      .def_readonly("log10", &DepthMetrics::log10)
      .def_readonly("delta1", &DepthMetrics::delta1)
      .def_readonly("delta2", &DepthMetrics::delta2)
      .def_readonly("delta3", &DepthMetrics::delta3)
      .def_readonly("coverage", &DepthMetrics::coverage)
      .def_readonly("num_gt", &DepthMetrics::num_gt)
      .def_readonly("num_evaluated", &DepthMetrics::num_evaluated)
      .def("as_dict", [](const DepthMetrics& d) {
        py::dict out;
        out["abs_rel"] = d.abs_rel;
        out["sq_rel"] = d.sq_rel;
        out["rmse"] = d.rmse;
        out["rmse_log"] = d.rmse_log;
        out["rmse_log10"] = d.rmse_log10;
        out["log10"] = d.log10;
        out["delta1"] = d.delta1;
        out["delta2"] = d.delta2;
        out["delta3"] = d.delta3;
        out["coverage"] = d.coverage;
        out["num_gt"] = d.num_gt;
        out["num_evaluated"] = d.num_evaluated;
        return out;
      });

  m.def(
      "depth_metrics",
      [](const py::handle& pred, const py::handle& truth, double max_depth) {
        const cv::Mat p = MetresFrom(pred, "pred"), t = MetresFrom(truth, "truth");
        if (p.size() != t.size()) throw py::value_error("pred and truth differ in size");
        if (!(max_depth > 0)) throw py::value_error("max_depth must be positive");
        return ComputeDepthMetrics(p, t, max_depth);
      },
      py::arg("pred"), py::arg("truth"), py::kw_only(),
      py::arg("max_depth") = std::numeric_limits<double>::infinity(),
      "Metrics over the pixels with 0 < truth <= max_depth (metres). Depths are float metres "
      "(NaN or 0 = no estimate) or uint16 millimetres (0 = none), as corridor_eval computes "
      "them.");
}

}  // namespace python
}  // namespace corridor
