#pragma once

namespace corridor {

// cv::BORDER_REFLECT_101 index of any i for a line of n >= 1 pixels (... 2 1 | 0 1 2 ... n-1 |
// n-2 ...), as cv::borderInterpolate gives it.
inline int Reflect101(int i, int n) {
  if (n == 1) return 0;
  const int period = 2 * n - 2;
  i %= period;
  if (i < 0) i += period;
  return i < n ? i : period - i;
}

}  // namespace corridor
