#include "mesh_raster.hpp"

#include <algorithm>
#include <cmath>

namespace meshstep::render {

namespace {

constexpr int kSubpixelBits = 8;  // llvmpipe's FIXED_ORDER
constexpr std::int32_t kOne = 1 << kSubpixelBits;
// Points further than this from the picture (pixels) are not snapped: their triangles go to
// GL, which clips them. Inside, the edge functions' products stay far within 64 bits.
constexpr float kBand = 16384.0f;

std::int64_t ceil_div(std::int64_t a, std::int64_t b) { return a >= 0 ? (a + b - 1) / b : -((-a) / b); }
std::int64_t floor_div(std::int64_t a, std::int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

// A float in 0..1 as llvmpipe writes it to an 8-bit channel.
std::uint32_t to_unorm8(float v) { return static_cast<std::uint32_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); }

// One edge a -> b of a triangle of positive area: E(p) = (b - a) x (p - a), positive inside.
struct Edge {
  std::int64_t dx, dy;  // b - a, in 1/256 pixel
  std::int64_t at_row_start;  // E at the first pixel centre of the box, plus the tie bias
  float to_pixels;      // E times this: the distance to the edge in pixels
};

Edge make_edge(const std::int32_t ax, const std::int32_t ay, const std::int32_t bx, const std::int32_t by,
               std::int64_t first_x, std::int64_t first_y) {
  Edge e;
  e.dx = std::int64_t{bx} - ax;
  e.dy = std::int64_t{by} - ay;
  // A pixel centre on the edge belongs to one of the two triangles that share it: the one
  // for which the edge runs up the picture (or, level, to the right). The neighbour runs the
  // edge the other way round, so exactly one of them takes the centre.
  const bool owns_ties = e.dy < 0 || (e.dy == 0 && e.dx > 0);
  e.at_row_start = e.dx * (first_y - ay) - e.dy * (first_x - ax) + (owns_ties ? 1 : 0);
  // Exact squares: the differences are below 2^23.
  const double length = std::sqrt(static_cast<double>(e.dx * e.dx + e.dy * e.dy));
  e.to_pixels = length > 0.0 ? static_cast<float>(1.0 / (length * kOne)) : 0.0f;
  return e;
}

}  // namespace

void MeshRaster::draw(const scene::MeshLayer& mesh, const WorldFrame& frame, const View& view, bool edges_on,
                      std::vector<std::uint32_t>& pixels, std::vector<std::uint32_t>& large) {
  large.clear();
  drawn_ = 0;
  const std::size_t n = mesh.points.size();
  snapped_.resize(n);
  usable_.resize(n);
  // The same float arithmetic as the vertex shader and the viewport transform, then the
  // snap to 1/256 pixel with pixel centres on whole numbers, as llvmpipe's setup does.
  const float w = static_cast<float>(view.width), h = static_cast<float>(view.height);
  const LocalToPixels& to = view.to_pixels;
  for (std::size_t i = 0; i < n; ++i) {
    const std::array<float, 2> local = frame.to_local(mesh.points[i]);
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

  // The mesh shader's colours: premultiplied fill, premultiplied edge (none when off).
  const scene::Rgba& ec = mesh.edge_color;
  const float edge_alpha = edges_on ? ec.a / 255.0f : 0.0f;
  const std::array<float, 4> edge{ec.r / 255.0f * edge_alpha, ec.g / 255.0f * edge_alpha,
                                  ec.b / 255.0f * edge_alpha, edge_alpha};
  const float half_width = 0.5f * mesh.edge_width_px;
  const std::int64_t span = std::int64_t{MeshRaster::kMaxSpan} * kOne;
  const std::int64_t last_column = view.width - 1, last_row = view.height - 1;
  const std::size_t width = static_cast<std::size_t>(view.width);

  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& v = mesh.triangles[t];
    if (v[0] >= n || v[1] >= n || v[2] >= n) continue;  // the GL pass leaves it out too
    const scene::Rgba color = t < mesh.fill.size() ? mesh.fill[t] : scene::Rgba{160, 160, 160, 255};
    if (!usable_[v[0]] || !usable_[v[1]] || !usable_[v[2]] || color.a != 255) {
      large.push_back(static_cast<std::uint32_t>(t));
      continue;
    }
    Snapped a = snapped_[v[0]], b = snapped_[v[1]], c = snapped_[v[2]];
    const std::int64_t min_x = std::min({a.x, b.x, c.x}), max_x = std::max({a.x, b.x, c.x});
    const std::int64_t min_y = std::min({a.y, b.y, c.y}), max_y = std::max({a.y, b.y, c.y});
    if (max_x - min_x > span || max_y - min_y > span) {
      large.push_back(static_cast<std::uint32_t>(t));
      continue;
    }
    ++drawn_;
    // The pixel centres in the box, within the picture.
    const std::int64_t c0 = std::max<std::int64_t>(ceil_div(min_x, kOne), 0);
    const std::int64_t c1 = std::min<std::int64_t>(floor_div(max_x, kOne), last_column);
    const std::int64_t r0 = std::max<std::int64_t>(ceil_div(min_y, kOne), 0);
    const std::int64_t r1 = std::min<std::int64_t>(floor_div(max_y, kOne), last_row);
    if (c0 > c1 || r0 > r1) continue;  // holds no pixel centre: draws nothing, as in llvmpipe
    std::int64_t area2 = (std::int64_t{b.x} - a.x) * (std::int64_t{c.y} - a.y) -
                         (std::int64_t{c.x} - a.x) * (std::int64_t{b.y} - a.y);
    if (area2 == 0) continue;  // llvmpipe culls it
    if (area2 < 0) std::swap(b, c), area2 = -area2;

    const std::int64_t first_x = c0 * kOne, first_y = r0 * kOne;
    const Edge e0 = make_edge(b.x, b.y, c.x, c.y, first_x, first_y);
    const Edge e1 = make_edge(c.x, c.y, a.x, a.y, first_x, first_y);
    const Edge e2 = make_edge(a.x, a.y, b.x, b.y, first_x, first_y);

    // shaders/mesh.vert: the edges fade with the triangle's size in pixels.
    const float size_px = static_cast<float>(std::sqrt(static_cast<double>(area2))) / kOne;
    const float fade = std::clamp(0.075f * size_px - 0.05f, 0.1f, 1.0f);
    const std::array<float, 3> fill{color.r / 255.0f, color.g / 255.0f, color.b / 255.0f};
    const std::array<float, 3> toward{(edge[0] - fill[0] * edge[3]) * fade, (edge[1] - fill[1] * edge[3]) * fade,
                                      (edge[2] - fill[2] * edge[3]) * fade};
    const std::uint32_t plain = pack_rgba(color.r, color.g, color.b, 255);

    std::int64_t row0 = e0.at_row_start, row1 = e1.at_row_start, row2 = e2.at_row_start;
    for (std::int64_t r = r0; r <= r1; ++r) {
      std::int64_t f0 = row0, f1 = row1, f2 = row2;
      std::uint32_t* out = pixels.data() + static_cast<std::size_t>(r) * width;
      for (std::int64_t col = c0; col <= c1; ++col) {
        if (((f0 - 1) | (f1 - 1) | (f2 - 1)) >= 0) {  // all three positive
          // mesh.frag: the fill, with the edge over it by the nearest edge's distance.
          const float to_edge = std::min({static_cast<float>(f0) * e0.to_pixels, static_cast<float>(f1) * e1.to_pixels,
                                          static_cast<float>(f2) * e2.to_pixels});
          const float cover = std::clamp(half_width - to_edge + 0.5f, 0.0f, 1.0f);
          out[col] = cover <= 0.0f ? plain
                                   : pack_rgba(to_unorm8(fill[0] + toward[0] * cover),
                                               to_unorm8(fill[1] + toward[1] * cover),
                                               to_unorm8(fill[2] + toward[2] * cover), 255);
        }
        f0 -= e0.dy * kOne, f1 -= e1.dy * kOne, f2 -= e2.dy * kOne;
      }
      row0 += e0.dx * kOne, row1 += e1.dx * kOne, row2 += e2.dx * kOne;
    }
  }
}

}  // namespace meshstep::render
