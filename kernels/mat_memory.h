#pragma once

// Matrices that keep their memory from call to call (a thread's scratch, a reused result).

#include <opencv2/core.hpp>

namespace corridor {

// Empties *m unless its pixels are its own alone: allocated by OpenCV and held by no other
// cv::Mat (a view or a shallow copy). A create() after it then never writes into pixels that
// something else still reads; with the same size and type it allocates nothing.
inline void ReleaseUnlessSole(cv::Mat* m) {
  if (m->data == nullptr) return;
  if (m->u == nullptr || CV_XADD(&m->u->refcount, 0) != 1) m->release();
}

}  // namespace corridor
