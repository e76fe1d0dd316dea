#include "meshstep/scene/scene.hpp"

#include <array>

namespace meshstep::scene {

namespace {

constexpr std::array<const char*, kLayerCount> kLayerNames = {
    "fill", "edges", "voronoi", "highlight", "overlay", "segments", "vertices", "holes", "labels", "caption", "legend"};
constexpr std::array<const char*, static_cast<std::size_t>(ColorBy::count_)> kColorByNames = {
    "none", "angle", "quality", "area", "region", "age", "height"};

}  // namespace

const char* name(Layer layer) { return kLayerNames[static_cast<std::size_t>(layer)]; }

std::optional<Layer> parse_layer(std::string_view text) {
  for (std::size_t i = 0; i < kLayerCount; ++i)
    if (text == kLayerNames[i]) return static_cast<Layer>(i);
  return std::nullopt;
}

const char* name(ColorBy c) { return kColorByNames[static_cast<std::size_t>(c)]; }

std::optional<ColorBy> parse_color_by(std::string_view text) {
  for (std::size_t i = 0; i < kColorByNames.size(); ++i)
    if (text == kColorByNames[i]) return static_cast<ColorBy>(i);
  return std::nullopt;
}

const Shape* Scene::find(std::string_view role) const {
  for (const Shape& s : shapes)
    if (s.role == role) return &s;
  return nullptr;
}

std::vector<const Shape*> Scene::find_all(std::string_view role) const {
  std::vector<const Shape*> out;
  for (const Shape& s : shapes)
    if (s.role == role) out.push_back(&s);
  return out;
}

}  // namespace meshstep::scene
