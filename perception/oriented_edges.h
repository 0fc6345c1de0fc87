#pragma once

// Helpers of the ceiling and end-wall searches: colour edges (ImageEdges, which the pipeline
// computes once for both when they search the same image), edges that know which way they run,
// and how well a projected line follows them.

#include <opencv2/core.hpp>

namespace corridor {

// Canny edges (20 / 60, L2) of the colour gradient of the image rows [from, to), after the
// binomial blur of sigma 1 (binomial_blur.h, which reads the rows just outside the range where the
// image has them). dx and dy get the gradient, edges 255 on edges; all to - from rows. False
// (and nothing written) for an image that is not 8-bit or an empty or out-of-range row range.
// Colour edges: a green wall under a grey ceiling, or a dark baseboard on a dark floor, has
// hardly any grey edge.
// `smooth`, when given, gets the blurred rows.
bool ColorCannyEdges(const cv::Mat& bgr, int from, int to, cv::Mat* dx, cv::Mat* dy,
                     cv::Mat* edges, cv::Mat* smooth = nullptr);

// Gradient orientations in this many bins over 180 degrees, one bit each.
constexpr int kOrientationBins = 8;

// The bin of the gradient (gx, gy): floor(angle / 22.5 deg), angle = atan2(gy, gx) taken into
// [0, 180] degrees (180 in the last bin; (0, 0) in bin 0). Comparisons with the bin edges'
// tangents instead of atan2: the same bins for every integer gradient a Sobel can give.
int OrientationBin(int gx, int gy);

// Canny edges of the colour gradient on the image rows [top, bottom), each with its orientation.
struct OrientedEdges {
  int top = 0;    // First image row of the band.
  cv::Mat edges;  // CV_8U, 255 = edge (band rows).
  cv::Mat near;   // CV_8U: bit b set where an edge of orientation bin b lies within 1 px.
};

// ColorCannyEdges of an image's rows from the top down, computed once for every search of a frame
// that reads that image: all of them (ComputeImageEdges), or as far down as the ceiling searches
// need (ComputeOrientedEdges keeps them).
struct ImageEdges {
  cv::Mat dx, dy;      // CV_16S colour gradient of rows [0, edges.rows).
  cv::Mat edges;       // CV_8U, 255 = edge.
  cv::Mat smooth;      // The blurred rows [0, edges.rows) (the image's type): PyrDown reuses them.
  int image_rows = 0;  // Rows of the image they are of.
  // True when these are the edges of the whole of an image of `image`'s size.
  bool Fits(const cv::Mat& image) const { return Covers(image, image.rows); }
  // True when rows down to `bottom` of an image of `image`'s size can be cut from these: the whole
  // image, or rows computed at least a blur and hysteresis margin below `bottom`.
  bool Covers(const cv::Mat& image, int bottom) const;
};

// The whole image's edges; false (and *out empty) for an image that is not 8-bit or is empty.
bool ComputeImageEdges(const cv::Mat& bgr, ImageEdges* out);

// Edges of rows [top, bottom) (clamped to the image). Without `cache`: computed with a few rows of
// margin so that the blur and Canny's hysteresis see nearly what they would see over the whole
// image. With it: cut from *cache when it covers the rows; otherwise the image's rows from the top
// down to a little below `bottom` (slack for the next search of the frame) are computed into
// *cache first.
OrientedEdges ComputeOrientedEdges(const cv::Mat& bgr, int top, int bottom,
                                   ImageEdges* cache = nullptr);

// How well a projected line follows the edges: of its visible samples (x >= 0; rows inside the
// band), those that have an edge within 1 px running along the line, its gradient within one
// orientation bin (22.5 degrees) of the line's normal, so that crossing edges (lights, door frames,
// clutter) do not count.
struct LineHits {
  int hits = 0;     // Visible samples with an edge along the line within 1 px (0 below 8 visible).
  int visible = 0;  // Samples inside the band.
  // hits / max(visible, at_least); 0 with fewer than 8 visible samples. `at_least` keeps a line
  // with few visible samples (one that leaves the image near the vanishing point, where every
  // edge converges) from scoring high.
  double Fraction(int at_least) const;
};
LineHits OrientedLineHits(const cv::Point* line, int samples, const OrientedEdges& edges);

}  // namespace corridor
