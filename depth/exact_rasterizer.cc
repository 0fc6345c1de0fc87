#include "depth/exact_rasterizer.h"

#include <cmath>
#include <limits>

#include "corridor_depth/corridor_frame.h"
#include "core/cpu_features.h"

namespace corridor {
namespace {

// The per-frame constants of the box model.
struct BoxModel {
  float n_y, n_z;         // Floor normal (n_x = 0).
  float m_x, m_y, m_z;    // Wall normal.
  float h;                // Camera height.
  float d_left, d_right;  // Distances to the walls.
  float ceiling_y;        // Y_W of the ceiling (h - H_c, negative), or 0 when unknown.
  bool has_ceiling;       // Render the ceiling.
  float min_wall_y;       // Without a ceiling: wall points with Y_W below this get 0.
  float max_range;        // Depth cap.
  float d_x, d_y, d_z;    // Corridor axis (for the end wall).
  float end;              // Z_W of the end wall, or +inf when there is none.

  // Depth of the ray (x, y, 1); 0 when no modelled surface is hit within range.
  float Depth(float x, float y) const {
    const float nr = n_y * y + n_z;
    const float mr = m_x * x + m_y * y + m_z;
    float z = std::numeric_limits<float>::infinity();
    if (nr > 0) z = h / nr;
    bool wall = false;
    if (mr < 0) {
      const float zw = -d_left / mr;
      if (zw < z) z = zw, wall = true;
    } else if (mr > 0) {
      const float zw = d_right / mr;
      if (zw < z) z = zw, wall = true;
    }
    if (has_ceiling && nr < 0) {
      const float zc = ceiling_y / nr;
      if (zc < z) z = zc, wall = false;
    }
    const float dr = d_x * x + d_y * y + d_z;
    if (dr > 0 && end / dr < z) z = end / dr, wall = true;  // The end wall hides what is beyond.
    if (!(z <= max_range)) return 0.0f;
    if (wall && !has_ceiling && z * nr < min_wall_y) return 0.0f;
    return z;
  }
};

BoxModel MakeBoxModel(const CorridorGeometry& g, const RasterizerOptions& options) {
  const CorridorRotation<double> r(g.pitch, g.yaw);
  const Vec3<double> n = r.FloorNormal(), m = r.WallNormal();
  BoxModel box;
  box.n_y = static_cast<float>(n.y);
  box.n_z = static_cast<float>(n.z);
  box.m_x = static_cast<float>(m.x);
  box.m_y = static_cast<float>(m.y);
  box.m_z = static_cast<float>(m.z);
  box.h = static_cast<float>(g.camera_height);
  box.d_left = static_cast<float>(g.LeftDistance());
  box.d_right = static_cast<float>(g.RightDistance());
  box.has_ceiling = options.use_ceiling && g.HasCeiling();
  box.ceiling_y = static_cast<float>(g.camera_height - g.ceiling_height);
  box.min_wall_y = static_cast<float>(g.camera_height - options.max_height);
  box.max_range = static_cast<float>(options.max_range);
  const Vec3<double> d = r.Axis();
  box.d_x = static_cast<float>(d.x);
  box.d_y = static_cast<float>(d.y);
  box.d_z = static_cast<float>(d.z);
  box.end = g.HasEndWall() ? static_cast<float>(g.end_distance)
                           : std::numeric_limits<float>::infinity();
  return box;
}

// The per-row constants of the undistorted loop.
struct RowConstants {
  float nr;            // n.r of the row (n has no x part).
  float z_plane;       // Floor depth, or the ceiling's above the horizon (inf: neither).
  float mr0, mr_step;  // m.r at u = 0, and its change per pixel.
  float dr0, dr_step;  // d.r (corridor axis) at u = 0, and its change per pixel.
};

using RowKernel = void (*)(const BoxModel&, const RowConstants&, int, int, float, float*);

// Pixels [first, last) of one row of the undistorted image; `none` where there is no estimate.
// kEndWall: an end wall may hide what is beyond; kCutWalls (no ceiling): wall points above
// max_height get `none`. Bitwise, not short-circuit,
// operators and selects: no branches, so the loop vectorises.
template <bool kEndWall, bool kCutWalls>
CORRIDOR_ALWAYS_INLINE inline void RowBody(const BoxModel& box, const RowConstants& row, int first,
                                           int last, float none, float* out) {
  const float inf = std::numeric_limits<float>::infinity();
  for (int u = first; u < last; ++u) {
    const float mr = row.mr0 + row.mr_step * u;
    const float wall_distance = mr < 0 ? box.d_left : box.d_right;
    const float z_wall = wall_distance / std::abs(mr);  // +inf when the ray is parallel.
    const bool side = z_wall < row.z_plane;
    float z = side ? z_wall : row.z_plane;
    bool wall = side;
    if (kEndWall) {
      const float dr = row.dr0 + row.dr_step * u;
      // inf when the ray points away from the end wall (d.r <= 0: the quotient is <= 0 or
      // -inf). Selected on the quotient, not on d.r: GCC would move a division used only under
      // `dr > 0` into a branch, and a branch keeps the loop from vectorising.
      const float end_over_dr = box.end / dr;
      const float z_end = end_over_dr > 0 ? end_over_dr : inf;
      const bool end = z_end < z;  // The end wall hides what is beyond.
      wall = wall | end;
      z = end ? z_end : z;
    }
    bool keep = z <= box.max_range;
    if (kCutWalls) keep = keep & !(wall & (z * row.nr < box.min_wall_y));
    out[u] = keep ? z : none;
  }
}

template <bool kEndWall, bool kCutWalls>
void Row(const BoxModel& box, const RowConstants& row, int first, int last, float none,
         float* out) {
  RowBody<kEndWall, kCutWalls>(box, row, first, last, none, out);
}

#ifdef CORRIDOR_AVX2_VARIANTS
// The same loop compiled for AVX2 (8 floats a step; no FMA, so that every product is rounded
// as in the baseline loop).
template <bool kEndWall, bool kCutWalls>
__attribute__((target("avx2"))) void RowAvx2(const BoxModel& box, const RowConstants& row,
                                             int first, int last, float none, float* out) {
  RowBody<kEndWall, kCutWalls>(box, row, first, last, none, out);
}
#endif

RowKernel ChooseRowKernel(bool end_wall, bool cut_walls, bool allow_avx2) {
#ifdef CORRIDOR_AVX2_VARIANTS
  if (allow_avx2 && CpuHasAvx2()) {
    if (end_wall) return cut_walls ? RowAvx2<true, true> : RowAvx2<true, false>;
    return cut_walls ? RowAvx2<false, true> : RowAvx2<false, false>;
  }
#else
  (void)allow_avx2;
#endif
  if (end_wall) return cut_walls ? Row<true, true> : Row<true, false>;
  return cut_walls ? Row<false, true> : Row<false, false>;
}

// The pixels [*begin, *end) of a row where the floor or ceiling plane (depth row.z_plane, no end
// wall) is nearer than both walls by a safe margin, so that RowBody would pick the plane there:
// the walls' depth d / |m.r| exceeds z_plane wherever -d_left / z_plane < m.r < d_right / z_plane,
// and m.r is affine in u. The bounds are pulled in by 1e-4 relatively and by far more than the
// float rounding of m.r, and by a pixel at each end; an empty span when in doubt.
void PlaneSpan(const BoxModel& box, const RowConstants& row, int width, int* begin, int* end) {
  *begin = *end = 0;
  const double z = row.z_plane;
  if (!(z > 0) || !std::isfinite(z)) return;
  const double mr0 = row.mr0, step = row.mr_step;
  const double slack = 1e-5 * (std::abs(mr0) + std::abs(step) * width);
  const double lo = -box.d_left / z * (1 - 1e-4) + slack;
  const double hi = box.d_right / z * (1 - 1e-4) - slack;
  if (!(lo < hi)) return;
  double u_lo, u_hi;  // m.r in [lo, hi] for u in [u_lo, u_hi].
  if (std::abs(step) < 1e-12) {
    if (mr0 < lo || mr0 > hi) return;
    u_lo = 0;
    u_hi = width;
  } else {
    u_lo = ((step > 0 ? lo : hi) - mr0) / step;
    u_hi = ((step > 0 ? hi : lo) - mr0) / step;
  }
  if (!(u_lo <= u_hi)) return;  // Also NaN.
  const double first = std::max(0.0, std::ceil(u_lo) + 1);
  const double last = std::min(1.0 * width, std::floor(u_hi));
  if (!(first < last)) return;
  *begin = static_cast<int>(first);
  *end = static_cast<int>(last);
}

}  // namespace

std::shared_ptr<const RayTable> ExactRasterizer::TableFor(const Camera& camera) const {
  std::lock_guard<std::mutex> lock(table_mutex_);
  if (!table_ || !table_->Matches(camera)) table_ = std::make_shared<RayTable>(camera);
  return table_;
}

Status ExactRasterizer::Render(const CorridorGeometry& geometry, const Camera& camera,
                               cv::Mat* depth) const {
  return RenderWith(geometry, camera, 0.0f, depth);
}

Status ExactRasterizer::RenderNoEstimateNaN(const CorridorGeometry& geometry,
                                            const Camera& camera, cv::Mat* depth) const {
  return RenderWith(geometry, camera, std::numeric_limits<float>::quiet_NaN(), depth);
}

Status ExactRasterizer::RenderWith(const CorridorGeometry& geometry, const Camera& camera,
                                   float none, cv::Mat* depth) const {
  std::string why;
  if (!camera.CheckIntrinsics(&why)) return Status::InvalidArgument("camera: " + why);
  const Status valid = CheckGeometryForRendering(geometry);
  if (!valid.ok()) return valid;
  const BoxModel box = MakeBoxModel(geometry, options_);
  depth->create(camera.image_height, camera.image_width, CV_32F);
  if (camera.HasDistortion()) {
    const auto table = TableFor(camera);
    for (int v = 0; v < camera.image_height; ++v) {
      float* out = depth->ptr<float>(v);
      const float* rx = table->row_x(v);
      const float* ry = table->row_y(v);
      for (int u = 0; u < camera.image_width; ++u) {
        const float z = box.Depth(rx[u], ry[u]);
        out[u] = z > 0 || none == 0 ? z : none;  // Depth's 0 is no estimate.
      }
    }
    return Status::Ok();
  }
  // Without distortion the ray's y is constant along a row, so the floor and ceiling depths are
  // too (n has no x part), and the wall's m.r is affine in u: a few operations per pixel.
  const float inv_fx = static_cast<float>(1.0 / camera.fx);
  const float x0 = static_cast<float>(-camera.cx / camera.fx);
  const float inf = std::numeric_limits<float>::infinity();
  const bool end_wall = std::isfinite(box.end);
  // Row kernels without the end wall's division, or the wall cut, where they do nothing; with AVX2
  // where the CPU has it (the same IEEE operations, so the same depths).
  const RowKernel kernel = ChooseRowKernel(end_wall, !box.has_ceiling, options_.use_avx2);
  for (int v = 0; v < camera.image_height; ++v) {
    const float y = static_cast<float>((v - camera.cy) / camera.fy);
    RowConstants row;
    row.nr = box.n_y * y + box.n_z;
    row.z_plane = row.nr > 0 ? box.h / row.nr : inf;  // Floor, or ceiling above the horizon.
    if (box.has_ceiling && row.nr < 0) row.z_plane = box.ceiling_y / row.nr;
    row.mr0 = box.m_x * x0 + box.m_y * y + box.m_z;
    row.mr_step = box.m_x * inv_fx;
    row.dr0 = box.d_x * x0 + box.d_y * y + box.d_z;  // The axis' d.r, affine in u too.
    row.dr_step = box.d_x * inv_fx;
    float* out = depth->ptr<float>(v);
    int begin = 0, end = 0;
    if (options_.plane_spans && !end_wall) PlaneSpan(box, row, camera.image_width, &begin, &end);
    if (begin < end) {
      // The plane is nearest: RowBody's depth there is z_plane, or none beyond the range.
      std::fill(out + begin, out + end, row.z_plane <= box.max_range ? row.z_plane : none);
      kernel(box, row, 0, begin, none, out);
      kernel(box, row, end, camera.image_width, none, out);
    } else {
      kernel(box, row, 0, camera.image_width, none, out);
    }
  }
  return Status::Ok();
}

}  // namespace corridor
