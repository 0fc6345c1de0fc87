#pragma once

// One row of the 3x3 horizontal Sobel of an 8-bit plane, and where it is strong.

#include <cstdint>

namespace corridor {

// g[x] = (up[x+1] - up[x-1]) + 2 (mid[x+1] - mid[x-1]) + (down[x+1] - down[x-1]) (cv::Sobel's
// dx = 1 kernel on the three rows around one), and strong[x] nonzero exactly where |g[x]| >=
// threshold, for x in [begin, end); each row is read from begin - 1 to end. |g| <= 1020: a
// threshold above 1020 marks nothing. Sixteen columns at a time with AVX2 where the CPU has it.
void SobelXRow(const uint8_t* up, const uint8_t* mid, const uint8_t* down, int begin, int end,
               int threshold, int16_t* g, uint8_t* strong);

}  // namespace corridor
