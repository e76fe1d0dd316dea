#include "render_test_support.hpp"

#include <filesystem>

namespace meshstep::render::testing {

scene::Scene test_scene() {
  scene::Scene s;
  s.background = kBackground;
  s.caption_color = kText;
  s.caption = "meshstep renderer test";

  s.mesh.points = {{10, 10}, {50, 10}, {50, 50}, {10, 50}};
  s.mesh.triangles = {{0, 1, 3}, {1, 2, 3}};
  s.mesh.fill = {kRed, kGreen};
  s.mesh.edge_color = kEdge;
  s.mesh.edge_width_px = 1.0f;

  scene::Shape line;
  line.layer = scene::Layer::segments;
  line.kind = scene::ShapeKind::lines;
  line.role = "solid_line";
  line.color = kBlue;
  line.width_px = 6.0f;
  line.points = {{10, 80}, {90, 80}};
  s.shapes.push_back(line);

  scene::Shape dashed = line;
  dashed.role = "dashed_line";
  dashed.color = kPurple;
  dashed.width_px = 4.0f;
  dashed.dashed = true;
  dashed.points = {{15, 90}, {85, 90}};
  s.shapes.push_back(dashed);

  scene::Shape circle;
  circle.layer = scene::Layer::overlay;
  circle.kind = scene::ShapeKind::circles;
  circle.role = "circle";
  circle.color = kRing;
  circle.width_px = 3.0f;
  circle.points = {{70, 40}};
  circle.radii = {10};
  s.shapes.push_back(circle);

  scene::Shape marker;
  marker.layer = scene::Layer::vertices;
  marker.kind = scene::ShapeKind::markers;
  marker.role = "marker";
  marker.marker = scene::Marker::disc;
  marker.color = kMarker;
  marker.marker_px = 10.0f;
  marker.width_px = 1.0f;
  marker.points = {{80, 85}};
  s.shapes.push_back(marker);

  s.bounds = BBox{{10, 10}, {90, 90}};
  return s;
}

scene::Camera test_camera(int width, int height) { return scene::Camera({50, 50}, 4.0, width, height); }

int dark_pixels(const scene::Image& image, int x0, int y0, int x1, int y1, int below) {
  int n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) n += luminance(pixel(image, x, y)) < below;
  return n;
}

std::string save_for_inspection(const scene::Image& image, const std::string& name) {
  const std::filesystem::path path = std::filesystem::path(::testing::TempDir()) / (name + ".png");
  scene::write_png(path.string(), image, 1);
  return path.string();
}

const char* backend_label(Backend backend) { return backend == Backend::egl ? "EGL" : "OSMesa"; }

void RenderTest::SetUp() {
  try {
    context_ = make_offscreen_context(GetParam());
  } catch (const GlUnavailable& e) {
    GTEST_SKIP() << e.what();
  }
  renderer_ = std::make_unique<Renderer>();
}

void RenderTest::TearDown() {
  renderer_.reset();  // its GL objects go while the context is still there
  context_.reset();
}

scene::Image RenderTest::draw(const scene::Scene& scene, const scene::Camera& camera, int samples) {
  renderer_->render(scene, camera, samples);
  return renderer_->read_pixels();
}

}  // namespace meshstep::render::testing
