#include "mesh_raster.hpp"

#include <algorithm>
#include <cmath>

namespace meshstep::render {

namespace {

constexpr int kSubpixelBits = 8;  // llvmpipe's FIXED_ORDER
constexpr std::int32_t kOne = 1 << kSubpixelBits;
// Points further than this from the picture (pixels) are not snapped: their triangles go to
// GL, which clips them. Inside, the snapped coordinates stay below 2^23.
constexpr float kBand = 16384.0f;

// One edge a -> b of a triangle of positive area: E(p) = (b - a) x (p - a), positive inside.
// Over a box of at most kMaxSpan + 1 pixels a side next to the triangle, E stays below 2^31.
struct Edge {
  std::int32_t step_x, step_y;  // E's change from one pixel centre to the next
  std::int32_t at_first;        // at the box's first pixel centre, plus the tie bias
  float to_pixels;              // E times this: the distance to the edge in pixels
};

Edge make_edge(std::int32_t ax, std::int32_t ay, std::int32_t bx, std::int32_t by, std::int32_t first_x,
               std::int32_t first_y) {
  const std::int32_t dx = bx - ax, dy = by - ay;
  // A pixel centre on the edge belongs to one of the two triangles that share it: the one
  // for which the edge runs up the picture (or, level, to the right). The neighbour runs the
  // edge the other way round, so exactly one of them takes the centre.
  const bool owns_ties = dy < 0 || (dy == 0 && dx > 0);
  Edge e;
  e.step_x = -dy * kOne;
  e.step_y = dx * kOne;
  e.at_first = dx * (first_y - ay) - dy * (first_x - ax) + (owns_ties ? 1 : 0);
  const float length = std::sqrt(static_cast<float>(dx) * static_cast<float>(dx) + static_cast<float>(dy) * static_cast<float>(dy));
  e.to_pixels = length > 0.0f ? 1.0f / (length * kOne) : 0.0f;
  return e;
}

}  // namespace

void MeshRaster::draw(const scene::MeshLayer& mesh, const WorldFrame& frame, const View& view, bool edges_on,
                      std::vector<std::uint32_t>& pixels, std::vector<std::uint32_t>& large) {
  large.clear();
  helper_large_.clear();
  const std::size_t n = mesh.points.size(), triangles = mesh.triangles.size();
  snapped_.resize(n);
  usable_.resize(n);
  const Job job{&mesh, &frame, &view, edges_on, pixels.data()};
  // Small meshes are not worth a hand-over (a few microseconds each way).
  constexpr std::size_t kSplitAbove = 20000;
  if (triangles < kSplitAbove) {
    snap_points(job, 0, n);
    drawn_ = draw_triangles(job, 0, triangles, large);
    return;
  }
  if (!helper_) helper_ = std::make_unique<HelperThread>();
  // Two halves of the points, then of the triangles. The triangles' halves write different
  // pixels (each pixel centre belongs to one triangle), so they need no lock.
  auto helper_points = [&] { snap_points(job, n / 2, n); };
  helper_->split(helper_points, [&] { snap_points(job, 0, n / 2); });
  std::size_t helper_drawn = 0;
  auto helper_triangles = [&] { helper_drawn = draw_triangles(job, triangles / 2, triangles, helper_large_); };
  std::size_t caller_drawn = 0;
  helper_->split(helper_triangles, [&] { caller_drawn = draw_triangles(job, 0, triangles / 2, large); });
  large.insert(large.end(), helper_large_.begin(), helper_large_.end());  // in index order
  drawn_ = caller_drawn + helper_drawn;
}

void MeshRaster::snap_points(const Job& job, std::size_t begin, std::size_t end) {
  // The same float arithmetic as the vertex shader and the viewport transform, then the
  // snap to 1/256 pixel with pixel centres on whole numbers, as llvmpipe's setup does.
  const float w = static_cast<float>(job.view->width), h = static_cast<float>(job.view->height);
  const LocalToPixels& to = job.view->to_pixels;
  const std::vector<Point>& points = job.mesh->points;
  for (std::size_t i = begin; i < end; ++i) {
    const std::array<float, 2> local = job.frame->to_local(points[i]);
    const float px = local[0] * to.scale[0] + to.offset[0];
    const float py = local[1] * to.scale[1] + to.offset[1];
    const float wx = (2.0f * px / w - 1.0f + 1.0f) * (0.5f * w);
    const float wy = (2.0f * py / h - 1.0f + 1.0f) * (0.5f * h);
    const bool ok = std::abs(wx) < kBand && std::abs(wy) < kBand;
    usable_[i] = ok;
    snapped_[i] = ok ? Snapped{static_cast<std::int32_t>(std::lrint((wx - 0.5f) * kOne)),
                               static_cast<std::int32_t>(std::lrint((wy - 0.5f) * kOne))}
                     : Snapped{0, 0};
  }
}

std::size_t MeshRaster::draw_triangles(const Job& job, std::size_t begin, std::size_t end,
                                       std::vector<std::uint32_t>& large) const {
  const scene::MeshLayer& mesh = *job.mesh;
  const View& view = *job.view;
  const bool edges_on = job.edges_on;
  const std::size_t n = mesh.points.size();
  std::size_t drawn = 0;
  // The mesh shader's colours: premultiplied fill, premultiplied edge (none when off).
  const scene::Rgba& ec = mesh.edge_color;
  const float edge_alpha = edges_on ? ec.a / 255.0f : 0.0f;
  const std::array<float, 4> edge{ec.r / 255.0f * edge_alpha, ec.g / 255.0f * edge_alpha,
                                  ec.b / 255.0f * edge_alpha, edge_alpha};
  const float half_width = 0.5f * mesh.edge_width_px;
  const std::int32_t span = MeshRaster::kMaxSpan * kOne;
  const std::int32_t last_column = view.width - 1, last_row = view.height - 1;
  const std::size_t width = static_cast<std::size_t>(view.width);

  for (std::size_t t = begin; t < end; ++t) {
    const auto& v = mesh.triangles[t];
    if (v[0] >= n || v[1] >= n || v[2] >= n) continue;  // the GL pass leaves it out too
    const scene::Rgba color = t < mesh.fill.size() ? mesh.fill[t] : scene::Rgba{160, 160, 160, 255};
    if (!usable_[v[0]] || !usable_[v[1]] || !usable_[v[2]] || color.a != 255) {
      large.push_back(static_cast<std::uint32_t>(t));
      continue;
    }
    Snapped a = snapped_[v[0]], b = snapped_[v[1]], c = snapped_[v[2]];
    const std::int32_t min_x = std::min({a.x, b.x, c.x}), max_x = std::max({a.x, b.x, c.x});
    const std::int32_t min_y = std::min({a.y, b.y, c.y}), max_y = std::max({a.y, b.y, c.y});
    if (max_x - min_x > span || max_y - min_y > span) {
      large.push_back(static_cast<std::uint32_t>(t));
      continue;
    }
    ++drawn;
    // The pixel centres in the box, within the picture (>> rounds toward minus infinity).
    const std::int32_t c0 = std::max((min_x + kOne - 1) >> kSubpixelBits, 0);
    const std::int32_t c1 = std::min(max_x >> kSubpixelBits, last_column);
    const std::int32_t r0 = std::max((min_y + kOne - 1) >> kSubpixelBits, 0);
    const std::int32_t r1 = std::min(max_y >> kSubpixelBits, last_row);
    if (c0 > c1 || r0 > r1) continue;  // holds no pixel centre: draws nothing, as in llvmpipe
    // Twice the area, below 2^31 within a box of kMaxSpan pixels.
    std::int32_t area2 = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    if (area2 == 0) continue;  // llvmpipe culls it
    if (area2 < 0) std::swap(b, c), area2 = -area2;

    const std::int32_t first_x = c0 * kOne, first_y = r0 * kOne;
    const Edge e0 = make_edge(b.x, b.y, c.x, c.y, first_x, first_y);
    const Edge e1 = make_edge(c.x, c.y, a.x, a.y, first_x, first_y);
    const Edge e2 = make_edge(a.x, a.y, b.x, b.y, first_x, first_y);

    // shaders/mesh.vert: the edges fade with the triangle's size in pixels; mesh.frag: the
    // fill with the edge over it, by the nearest edge's distance (a mix of two colours in
    // 0..1, so rounding needs no clamp). Kept in 0..255 with the rounding's half added.
    const float size_px = std::sqrt(static_cast<float>(area2)) / kOne;
    const float fade = std::clamp(0.075f * size_px - 0.05f, 0.1f, 1.0f);
    const std::array<float, 3> fill{color.r / 255.0f, color.g / 255.0f, color.b / 255.0f};
    const std::array<float, 3> base{color.r + 0.5f, color.g + 0.5f, color.b + 0.5f};
    const std::array<float, 3> toward{(edge[0] - fill[0] * edge[3]) * fade * 255.0f,
                                      (edge[1] - fill[1] * edge[3]) * fade * 255.0f,
                                      (edge[2] - fill[2] * edge[3]) * fade * 255.0f};
    const float cover_at_edge = half_width + 0.5f;

    std::int32_t row0 = e0.at_first, row1 = e1.at_first, row2 = e2.at_first;
    for (std::int32_t r = r0; r <= r1; ++r) {
      std::int32_t f0 = row0, f1 = row1, f2 = row2;
      std::uint32_t* out = job.pixels + static_cast<std::size_t>(r) * width;
      for (std::int32_t col = c0; col <= c1; ++col) {
        if (((f0 - 1) | (f1 - 1) | (f2 - 1)) >= 0) {  // all three positive
          const float to_edge = std::min({static_cast<float>(f0) * e0.to_pixels, static_cast<float>(f1) * e1.to_pixels,
                                          static_cast<float>(f2) * e2.to_pixels});
          const float cover = std::clamp(cover_at_edge - to_edge, 0.0f, 1.0f);
          out[col] = pack_rgba(static_cast<std::uint32_t>(base[0] + toward[0] * cover),
                               static_cast<std::uint32_t>(base[1] + toward[1] * cover),
                               static_cast<std::uint32_t>(base[2] + toward[2] * cover), 255);
        }
        f0 += e0.step_x, f1 += e1.step_x, f2 += e2.step_x;
      }
      row0 += e0.step_y, row1 += e1.step_y, row2 += e2.step_y;
    }
  }
  return drawn;
}

}  // namespace meshstep::render
