#include "draw_options.hpp"

#include <charconv>
#include <cmath>
#include <string_view>
#include <vector>

namespace meshstep::app {
namespace {

constexpr int kMaxPictureSide = 16384;

std::vector<std::string_view> split(std::string_view text, char sep) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = text.find(sep, start);
    parts.push_back(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (end == std::string_view::npos) return parts;
    start = end + 1;
  }
}

template <class T>
bool parse_number(std::string_view text, T& out) {
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, out);
  return ec == std::errc() && ptr == end;
}

void parse_size(const std::string& text, int& width, int& height) {
  const auto parts = split(text, 'x');
  if (parts.size() != 2 || !parse_number(parts[0], width) || !parse_number(parts[1], height) || width < 16 ||
      height < 16 || width > kMaxPictureSide || height > kMaxPictureSide)
    throw UsageError("--size " + text + ": expected WIDTHxHEIGHT in pixels, each from 16 to " +
                     std::to_string(kMaxPictureSide) + " (e.g. 1280x720)");
}

BBox parse_view(const std::string& text) {
  const auto parts = split(text, ',');
  double v[4];
  bool ok = parts.size() == 4;
  for (std::size_t i = 0; ok && i < 4; ++i) ok = parse_number(parts[i], v[i]) && std::isfinite(v[i]);
  if (!ok) throw UsageError("--view " + text + ": expected four numbers X0,Y0,X1,Y1 (the world window)");
  if (!(v[2] > v[0]) || !(v[3] > v[1]))
    throw UsageError("--view " + text + ": the window must have X1 > X0 and Y1 > Y0");
  BBox box;
  box.add({v[0], v[1]});
  box.add({v[2], v[3]});
  return box;
}

// "fill,edges,segments" is exactly those layers; "-caption,-legend" is the default set
// (every layer but voronoi) without those, "+voronoi" the default set with it; "all" and
// "none" start from every layer or none.
scene::LayerSet parse_layers(const std::string& text) {
  using scene::Layer;
  using scene::LayerSet;
  if (text.empty()) return LayerSet::standard();
  LayerSet set = LayerSet::standard();
  bool first_plain = true;
  for (std::string_view item : split(text, ',')) {
    if (item == "all") {
      set = LayerSet::all();
      first_plain = false;
      continue;
    }
    if (item == "none") {
      set = LayerSet::none();
      first_plain = false;
      continue;
    }
    const bool remove = item.starts_with('-'), add = item.starts_with('+');
    const std::string_view name = remove || add ? item.substr(1) : item;
    const std::optional<Layer> layer = scene::parse_layer(name);
    if (!layer) {
      std::string known;
      for (std::size_t i = 0; i < scene::kLayerCount; ++i)
        known += std::string(known.empty() ? "" : ", ") + scene::name(static_cast<Layer>(i));
      throw UsageError("--layers: unknown layer '" + std::string(name) + "' (layers: " + known + ", all, none)");
    }
    if (!remove && !add && first_plain) set = LayerSet::none();  // a plain list names exactly its layers
    if (!remove && !add) first_plain = false;
    set.set(*layer, !remove);
  }
  return set;
}

}  // namespace

void add_draw_options(CLI::App* cmd, DrawArgs& args) {
  cmd->add_option("--size", args.size, "Picture size WIDTHxHEIGHT in pixels (default 1280x720)");
  cmd->add_option("--view", args.view,
                  "World window X0,Y0,X1,Y1 to show (default: fit the whole mesh with a margin; the\n"
                  "window is centred and widened in one direction to the picture's aspect)");
  cmd->add_option("--color-by", args.color_by,
                  "Fill the triangles by: none, angle (smallest angle), quality (smallest angle against\n"
                  "the run's bound), area, region (attribute), age (the step that made it) or\n"
                  "height (a terrain's or a surface's run: the mean height of the corners)")
      ->default_str("none");
  cmd->add_option("--layers", args.layers,
                  "Layers to draw: a list of fill, edges, voronoi, highlight, overlay, segments,\n"
                  "vertices, holes, labels, caption, legend (exactly those), or changes to the\n"
                  "default set, every layer but voronoi (-caption,-legend or +voronoi); 'all'\n"
                  "(voronoi too) and 'none' too")
      ->default_str("all but voronoi");
  cmd->add_option("--theme", args.theme, "light (print), dark (screen) or high-contrast (projector)")->default_str("light");
  cmd->add_option("--gl", args.gl,
                  "OpenGL context for PNG pictures: auto (EGL, then OSMesa), egl or osmesa (the\n"
                  "environment variable MESHSTEP_GL says the same)")
      ->default_str("auto");
  cmd->add_option("--samples", args.samples,
                  "Multisampling: 1 (none; every line, circle and glyph is antialiased anyway), 2\n"
                  "or 4 (smooths the rim of the fill too, at up to twice the time)");
}

DrawSettings parse_draw_args(const DrawArgs& args) {
  DrawSettings s;
  parse_size(args.size, s.width, s.height);
  // Vertex markers only while they leave the mesh visible: about one per 30 x 30 pixels
  // (a 1280x720 picture marks up to 1,024 vertices).
  s.scene.max_vertex_markers = static_cast<std::size_t>(s.width) * s.height / 900;
  if (!args.view.empty()) s.view = parse_view(args.view);
  const std::optional<scene::ColorBy> color_by = scene::parse_color_by(args.color_by);
  if (!color_by)
    throw UsageError("--color-by " + args.color_by + ": expected none, angle, quality, area, region, age or height");
  s.scene.color_by = *color_by;
  s.scene.layers = parse_layers(args.layers);
  if (args.theme == "light") s.scene.theme = scene::Theme::light;
  else if (args.theme == "dark") s.scene.theme = scene::Theme::dark;
  else if (args.theme == "high-contrast") s.scene.theme = scene::Theme::high_contrast;
  else throw UsageError("--theme " + args.theme + ": expected light, dark or high-contrast");
  if (args.gl != "auto" && args.gl != "egl" && args.gl != "osmesa")
    throw UsageError("--gl " + args.gl + ": expected auto, egl or osmesa");
  s.gl = args.gl;
  if (args.samples != 0 && args.samples != 1 && args.samples != 2 && args.samples != 4)
    throw UsageError("--samples " + std::to_string(args.samples) + ": expected 1, 2 or 4");
  s.samples = args.samples;
  return s;
}

scene::Camera DrawSettings::camera(const BBox& bounds) const {
  return view ? scene::Camera::window(*view, width, height) : scene::Camera::fit(bounds, width, height);
}

}  // namespace meshstep::app
