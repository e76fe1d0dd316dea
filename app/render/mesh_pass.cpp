#include "mesh_pass.hpp"

#include <cmath>
#include <cstddef>

namespace meshstep::render {

namespace {

using Local = std::array<float, 2>;

// The three corners of a triangle with their heights and the triangle's size, from the
// float positions the GPU will draw (computed in double).
void add_corners(const Local& a, const Local& b, const Local& c, scene::Rgba color, std::vector<MeshVertex>& out) {
  const double ux = double(b[0]) - a[0], uy = double(b[1]) - a[1];
  const double vx = double(c[0]) - a[0], vy = double(c[1]) - a[1];
  const double twice_area = std::abs(ux * vy - uy * vx);
  // The height over an edge is twice the area over the edge's length.
  const auto height = [&](const Local& p, const Local& q) {
    const double length = std::hypot(double(q[0]) - p[0], double(q[1]) - p[1]);
    return length > 0.0 ? static_cast<float>(twice_area / length) : 0.0f;
  };
  const float size = static_cast<float>(std::sqrt(twice_area));
  out.push_back({a, color, height(b, c), size});
  out.push_back({b, color, height(c, a), size});
  out.push_back({c, color, height(a, b), size});
}

}  // namespace

MeshPass::MeshPass()
    : program_("mesh.vert", "mesh.frag"),
      view_uniforms_(program_),
      fill_on_(program_.uniform("u_fill_on")),
      edge_(program_.uniform("u_edge")),
      edge_half_width_(program_.uniform("u_edge_half_width")) {
  set_up(whole_);
  set_up(subset_);
}

void MeshPass::set_up(Buffers& b) {
  b.vao.bind();
  b.buffer.bind();
  float_attribute(0, 2, sizeof(MeshVertex), offsetof(MeshVertex, position), false);
  color_attribute(1, sizeof(MeshVertex), offsetof(MeshVertex, color), false);
  float_attribute(2, 1, sizeof(MeshVertex), offsetof(MeshVertex, height), false);
  float_attribute(3, 1, sizeof(MeshVertex), offsetof(MeshVertex, size), false);
  glBindVertexArray(0);
}

void MeshPass::fill_staging(const scene::MeshLayer& mesh, std::size_t t, Buffers& b) {
  constexpr scene::Rgba kNoColor{160, 160, 160, 255};
  const std::size_t n = mesh.points.size();
  const auto& v = mesh.triangles[t];
  if (v[0] >= n || v[1] >= n || v[2] >= n) return;
  const scene::Rgba color = t < mesh.fill.size() ? mesh.fill[t] : kNoColor;
  b.opaque = b.opaque && color.a == 255;
  add_corners(local_points_[v[0]], local_points_[v[1]], local_points_[v[2]], color, staging_);
}

void MeshPass::upload(const scene::MeshLayer& mesh, const WorldFrame& frame) {
  // Each point is converted once, then copied to the corners that share it.
  local_points_.resize(mesh.points.size());
  for (std::size_t i = 0; i < mesh.points.size(); ++i) local_points_[i] = frame.to_local(mesh.points[i]);
  staging_.clear();
  staging_.reserve(3 * mesh.triangles.size());
  whole_.opaque = true;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) fill_staging(mesh, t, whole_);
  whole_.buffer.upload(staging_);
  whole_.triangles = staging_.size() / 3;
}

void MeshPass::upload_subset(const scene::MeshLayer& mesh, const WorldFrame& frame,
                             const std::vector<std::uint32_t>& subset) {
  // Only the points the subset uses are converted (it is mostly empty).
  local_points_.resize(mesh.points.size());
  const std::size_t n = mesh.points.size();
  for (const std::uint32_t t : subset)
    for (const std::uint32_t v : mesh.triangles[t])
      if (v < n) local_points_[v] = frame.to_local(mesh.points[v]);
  staging_.clear();
  subset_.opaque = true;
  for (const std::uint32_t t : subset) fill_staging(mesh, t, subset_);
  subset_.buffer.upload(staging_);
  subset_.triangles = staging_.size() / 3;
}

void MeshPass::draw(const View& view, const scene::MeshLayer& style, bool fill_on, bool edges_on) const {
  draw(whole_, view, style, fill_on, edges_on);
}

void MeshPass::draw_subset(const View& view, const scene::MeshLayer& style, bool edges_on) const {
  draw(subset_, view, style, true, edges_on);
}

void MeshPass::draw(const Buffers& b, const View& view, const scene::MeshLayer& style, bool fill_on,
                    bool edges_on) const {
  if (b.triangles == 0 || (!fill_on && !edges_on)) return;
  program_.use();
  view_uniforms_.set(view);
  glUniform1f(fill_on_, fill_on ? 1.0f : 0.0f);
  // Premultiplied, and nothing when the edges are off (shaders/mesh.vert).
  const scene::Rgba& e = style.edge_color;
  const float alpha = edges_on ? e.a / 255.0f : 0.0f;
  glUniform4f(edge_, e.r / 255.0f * alpha, e.g / 255.0f * alpha, e.b / 255.0f * alpha, alpha);
  glUniform1f(edge_half_width_, 0.5f * style.edge_width_px);
  const bool blend = !(fill_on && b.opaque);
  if (!blend) glDisable(GL_BLEND);
  b.vao.bind();
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(3 * b.triangles));
  if (!blend) glEnable(GL_BLEND);
}

}  // namespace meshstep::render
