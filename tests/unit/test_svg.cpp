// The SVG writer: the document's structure (well-formed, one path per fill colour, every
// edge once, circles' pixel radii, escaped text, layers switched off left out), then the
// picture rsvg-convert draws from it (skipped when rsvg-convert is not installed).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "meshstep/scene/image.hpp"
#include "meshstep/scene/svg.hpp"
#include "temp_dir.hpp"

namespace meshstep::scene {
namespace {

using testing::TempDir;

// ---- reading the document back ----------------------------------------------------------

// Empty when `xml` is well-formed as far as a writer can get it wrong: every tag closed in
// order, attributes quoted, no raw '<' or stray '&' in text or attribute values.
std::string xml_problem(const std::string& xml) {
  std::vector<std::string> open;
  std::size_t i = 0;
  // A reference: a named entity or a character number, up to its ';'.
  const auto entity_ok = [&](std::size_t at) {
    const std::size_t end = xml.find(';', at);
    if (end == std::string::npos) return false;
    const std::string name = xml.substr(at + 1, end - at - 1);
    if (name == "amp" || name == "lt" || name == "gt" || name == "quot" || name == "apos") return true;
    if (name.size() < 2 || name[0] != '#') return false;
    const bool hex = name[1] == 'x';
    if (hex && name.size() < 3) return false;
    return std::all_of(name.begin() + (hex ? 2 : 1), name.end(), [&](char ch) {
      return hex ? std::isxdigit(static_cast<unsigned char>(ch)) != 0 : std::isdigit(static_cast<unsigned char>(ch)) != 0;
    });
  };
  while (i < xml.size()) {
    if (xml[i] == '&') {
      if (!entity_ok(i)) return "stray & at " + std::to_string(i);
      ++i;
      continue;
    }
    if (xml[i] != '<') {
      ++i;
      continue;
    }
    if (xml.compare(i, 2, "<?") == 0) {
      const std::size_t end = xml.find("?>", i);
      if (end == std::string::npos) return "unclosed <?";
      i = end + 2;
      continue;
    }
    const bool closing = xml.compare(i, 2, "</") == 0;
    std::size_t j = i + (closing ? 2 : 1);
    std::string name;
    while (j < xml.size() && (std::isalnum(static_cast<unsigned char>(xml[j])) || xml[j] == '-' || xml[j] == ':')) name += xml[j++];
    if (name.empty()) return "a tag without a name at " + std::to_string(i);
    // Attributes: name="value" pairs until '>' or '/>'.
    for (;;) {
      while (j < xml.size() && std::isspace(static_cast<unsigned char>(xml[j]))) ++j;
      if (j >= xml.size()) return "unterminated tag " + name;
      if (xml[j] == '>' || xml.compare(j, 2, "/>") == 0) break;
      if (closing) return "attributes in a closing tag";
      const std::size_t eq = xml.find('=', j);
      if (eq == std::string::npos || xml[eq + 1] != '"') return "unquoted attribute in " + name;
      const std::size_t end = xml.find('"', eq + 2);
      if (end == std::string::npos) return "unterminated attribute in " + name;
      for (std::size_t k = eq + 2; k < end; ++k) {
        if (xml[k] == '<') return "'<' in an attribute of " + name;
        if (xml[k] == '&' && !entity_ok(k)) return "stray & in an attribute of " + name;
      }
      j = end + 1;
    }
    const bool self_closing = xml[j] == '/';
    i = j + (self_closing ? 2 : 1);
    if (closing) {
      if (open.empty() || open.back() != name) return "</" + name + "> closes " + (open.empty() ? "nothing" : open.back());
      open.pop_back();
    } else if (!self_closing) {
      open.push_back(name);
    }
  }
  return open.empty() ? "" : "unclosed <" + open.back() + ">";
}

bool have_program(const std::string& name) {
  return std::system(("command -v " + name + " > /dev/null 2>&1").c_str()) == 0;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

// The text of the first element starting with `start` ("<g id=\"layer-fill\"") up to the
// first "</g>" after it (the groups looked at hold no nested group).
std::string group(const std::string& svg, const std::string& start) {
  const std::size_t from = svg.find(start);
  if (from == std::string::npos) return "";
  return svg.substr(from, svg.find("</g>", from) - from);
}

// Every value of an attribute in `text`, in order.
std::vector<std::string> attribute_values(const std::string& text, const std::string& name) {
  std::vector<std::string> values;
  const std::string key = " " + name + "=\"";
  for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + 1)) {
    const std::size_t from = at + key.size();
    values.push_back(text.substr(from, text.find('"', from) - from));
  }
  return values;
}

// Path data as absolute polylines (m, l, z, M, L, with implicit repeats; enough for what
// the writer emits apart from arcs).
std::vector<std::vector<Point>> polylines(const std::string& d) {
  std::vector<std::vector<Point>> lines;
  Point at{0, 0}, start{0, 0};
  char command = 0;
  std::size_t i = 0;
  const auto number = [&]() {
    while (i < d.size() && (d[i] == ' ' || d[i] == ',')) ++i;
    std::size_t used = 0;
    const double v = std::stod(d.substr(i), &used);
    i += used;
    return v;
  };
  while (i < d.size()) {
    const char c = d[i];
    if (c == ' ' || c == ',') {
      ++i;
      continue;
    }
    if (std::isalpha(static_cast<unsigned char>(c))) {
      command = c;
      ++i;
      if (c == 'z' || c == 'Z') {
        lines.back().push_back(start);
        at = start;
      }
      continue;
    }
    const double x = number(), y = number();
    const bool relative = std::islower(static_cast<unsigned char>(command));
    const Point p = relative ? Point{at.x + x, at.y + y} : Point{x, y};
    if (command == 'm' || command == 'M') {
      lines.push_back({p});
      start = p;
      command = relative ? 'l' : 'L';  // further pairs are line-tos
    } else {
      lines.back().push_back(p);
    }
    at = p;
  }
  return lines;
}

// ---- the scene ---------------------------------------------------------------------------

constexpr Rgba kBackground{10, 20, 30, 255};
constexpr Rgba kRed{200, 40, 40, 255};
constexpr Rgba kBlue{40, 60, 200, 255};
constexpr Rgba kGreen{0, 160, 0, 255};
constexpr Rgba kYellow{255, 255, 0, 255};

// World [0, 20] x [0, 10] on a 200 x 100 picture: 10 pixels per unit, y up.
Camera test_camera() { return Camera({10.0, 5.0}, 10.0, 200, 100); }

// Three triangles: A and C red, B blue; a 4-px green line along y = 1; a yellow circle of
// radius 1.5 around (15, 5).
Scene test_scene() {
  Scene s;
  s.background = kBackground;
  s.mesh.points = {{2, 2}, {8, 2}, {8, 8}, {2, 8}, {14, 2}};
  s.mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 2}};
  s.mesh.fill = {kRed, kBlue, kRed};
  s.mesh.edge_color = {0, 0, 0, 255};
  s.mesh.edge_width_px = 1.0f;
  s.bounds.add({0, 0});
  s.bounds.add({20, 10});

  Shape line;
  line.layer = Layer::segments;
  line.kind = ShapeKind::lines;
  line.role = "segment";
  line.color = kGreen;
  line.width_px = 4.0f;
  line.points = {{1, 1}, {19, 1}};
  s.shapes.push_back(line);

  Shape circle;
  circle.layer = Layer::overlay;
  circle.kind = ShapeKind::circles;
  circle.role = "flip_circle";
  circle.label = "in-circle test";
  circle.color = kYellow;
  circle.width_px = 3.0f;
  circle.points = {{15, 5}};
  circle.radii = {1.5};
  s.shapes.push_back(circle);
  return s;
}

// ---- structure ---------------------------------------------------------------------------

TEST(Svg, TheWellFormednessCheckerCatchesBrokenDocuments) {
  EXPECT_EQ(xml_problem("<?xml version=\"1.0\"?><a x=\"1\"><b/><c>t &amp; &#233;</c></a>"), "");
  for (const char* broken : {"<a><b></a>", "<a>", "<a x=1/>", "<a>x < y</a>", "<a>R&D</a>", "<a t=\"<\"/>", "</a>"})
    EXPECT_NE(xml_problem(broken), "") << broken;
}

TEST(Svg, IsWellFormed) {
  Scene s = test_scene();
  s.visible = LayerSet::all();  // the Voronoi layer, off by default, too
  s.caption = "refine · step 1 of 3 · <split> & \"go\"";
  s.labels.push_back({{5, 5}, "A & B <1>", {255, 255, 255, 255}, 12.0f, 2.0f, -2.0f});
  Shape markers;
  markers.layer = Layer::vertices;
  markers.kind = ShapeKind::markers;
  markers.role = "vertices";
  for (const Marker kind : {Marker::disc, Marker::ring, Marker::square, Marker::cross, Marker::diamond}) {
    markers.marker = kind;
    markers.points = {{3, 3}};
    s.shapes.push_back(markers);
  }
  Legend legend;
  legend.title = "smallest angle (degrees)";
  legend.colors = {{68, 1, 84, 255}, {33, 145, 140, 255}, {253, 231, 37, 255}};
  legend.ticks = {{0.0, "0"}, {1.0, "60"}};
  s.legend = legend;

  const std::string svg = to_svg(s, Camera({10.0, 5.0}, 30.0, 640, 360));
  EXPECT_EQ(xml_problem(svg), "");
  EXPECT_EQ(svg.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_NE(svg.find("width=\"640\" height=\"360\" viewBox=\"0 0 640 360\""), std::string::npos);
  // Every layer's group, in Layer order.
  std::size_t last = 0;
  for (std::size_t i = 0; i < kLayerCount; ++i) {
    const std::size_t at = svg.find(std::string("<g id=\"layer-") + name(static_cast<Layer>(i)) + "\"");
    ASSERT_NE(at, std::string::npos) << name(static_cast<Layer>(i));
    EXPECT_GT(at, last);
    last = at;
  }
  // The legend's bar: a gradient of its three stops.
  EXPECT_EQ(count(svg, "<linearGradient"), 1u);
  EXPECT_EQ(count(svg, "<stop "), 3u);

  if (!have_program("xmllint")) GTEST_SKIP() << "xmllint not installed: checked by the small checker only";
  TempDir dir;
  const std::string path = dir.write("scene.svg", svg);
  EXPECT_EQ(std::system(("xmllint --noout " + path).c_str()), 0);
}

TEST(Svg, OnePathPerFillColour) {
  const std::string fill = group(to_svg(test_scene(), test_camera()), "<g id=\"layer-fill\"");
  ASSERT_FALSE(fill.empty());
  const std::vector<std::string> colours = attribute_values(fill, "fill");
  EXPECT_EQ(std::multiset<std::string>(colours.begin(), colours.end()), (std::multiset<std::string>{"#c82828", "#283cc8"}));
  // The red path holds triangles A and C, the blue one B.
  const std::vector<std::string> paths = attribute_values(fill, "d");
  ASSERT_EQ(paths.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const std::vector<std::vector<Point>> triangles = polylines(paths[i]);
    EXPECT_EQ(triangles.size(), colours[i] == "#c82828" ? 2u : 1u);
    for (const auto& t : triangles) EXPECT_EQ(t.size(), 4u);  // three corners and back
  }
}

TEST(Svg, EveryEdgeOnce) {
  const Scene s = test_scene();
  const Camera camera = test_camera();
  const std::string edges = group(to_svg(s, camera), "<g id=\"layer-edges\"");
  const std::vector<std::string> paths = attribute_values(edges, "d");
  ASSERT_EQ(paths.size(), 1u);  // triangles of 60 px: full-strength edges, one path
  EXPECT_EQ(attribute_values(edges, "stroke"), std::vector<std::string>{"#000000"});
  EXPECT_EQ(attribute_values(edges, "stroke-width"), std::vector<std::string>{"1"});

  // The segments drawn, as pairs of mesh points.
  const auto point_at = [&](Point screen) {
    for (std::size_t i = 0; i < s.mesh.points.size(); ++i) {
      const Point p = camera.to_screen(s.mesh.points[i]);
      if (std::abs(p.x - screen.x) < 0.01 && std::abs(p.y - screen.y) < 0.01) return i;
    }
    ADD_FAILURE() << "no mesh point at " << screen.x << ", " << screen.y;
    return std::size_t{0};
  };
  std::multiset<std::pair<std::size_t, std::size_t>> drawn;
  for (const auto& line : polylines(paths[0]))
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
      const std::size_t a = point_at(line[i]), b = point_at(line[i + 1]);
      drawn.insert({std::min(a, b), std::max(a, b)});
    }
  const std::multiset<std::pair<std::size_t, std::size_t>> expected = {{0, 1}, {1, 2}, {0, 2}, {2, 3},
                                                                      {0, 3}, {1, 4}, {2, 4}};
  EXPECT_EQ(drawn, expected);
}

TEST(Svg, CircleRadiusIsInPixels) {
  const std::string circle = group(to_svg(test_scene(), test_camera()), "<g class=\"flip_circle\"");
  EXPECT_NE(circle.find("<circle cx=\"150\" cy=\"50\" r=\"15\"/>"), std::string::npos) << circle;
  EXPECT_NE(circle.find("<title>in-circle test</title>"), std::string::npos);
  EXPECT_NE(circle.find(" stroke=\"#ffff00\" stroke-width=\"3\""), std::string::npos);
  EXPECT_NE(circle.find(" fill=\"none\""), std::string::npos);
}

TEST(Svg, TextIsEscaped) {
  Scene s = test_scene();
  s.caption = "a<b & \"c\" 'd' · é";
  s.labels.push_back({{5, 5}, "x > y", {255, 255, 255, 255}, 12.0f, 0.0f, 0.0f});
  s.labels.push_back({{5, 3}, std::string("bad \xFF byte\x01"), {255, 255, 255, 255}, 12.0f, 0.0f, 0.0f});
  s.shapes[1].label = "<in> & out";
  const std::string svg = to_svg(s, test_camera());
  EXPECT_NE(svg.find(">a&lt;b &amp; &quot;c&quot; &apos;d&apos; · é</text>"), std::string::npos);
  EXPECT_NE(svg.find(">x &gt; y</text>"), std::string::npos);
  EXPECT_NE(svg.find(">bad \xEF\xBF\xBD byte\xEF\xBF\xBD</text>"), std::string::npos);
  EXPECT_NE(svg.find("<title>&lt;in&gt; &amp; out</title>"), std::string::npos);
  EXPECT_EQ(xml_problem(svg), "");
}

TEST(Svg, LayersSwitchedOffAreLeftOut) {
  Scene s = test_scene();
  s.caption = "caption";
  s.labels.push_back({{5, 5}, "label", {255, 255, 255, 255}, 12.0f, 0.0f, 0.0f});
  s.visible.set(Layer::overlay, false).set(Layer::fill, false).set(Layer::labels, false).set(Layer::caption, false)
      .set(Layer::highlight, false);
  const std::string svg = to_svg(s, test_camera());
  for (const char* absent : {"layer-overlay", "layer-fill", "layer-labels", "layer-caption", "layer-highlight",
                             "flip_circle", "<circle", "#c82828", "<text"})
    EXPECT_EQ(svg.find(absent), std::string::npos) << absent;
  for (const char* present : {"layer-edges", "layer-segments", "class=\"segment\""})
    EXPECT_NE(svg.find(present), std::string::npos) << present;
}

TEST(Svg, ClassAndIdComeFromTheRole) {
  Scene s = test_scene();
  s.shapes.push_back(s.shapes[1]);           // a second "flip_circle"
  s.shapes.push_back(s.shapes[0]);
  s.shapes.back().role = "lepp path #2";     // not a valid name as it is
  const std::string svg = to_svg(s, test_camera());
  EXPECT_NE(svg.find("<g class=\"flip_circle\" id=\"flip_circle\""), std::string::npos);
  EXPECT_NE(svg.find("<g class=\"flip_circle\" id=\"flip_circle-2\""), std::string::npos);
  EXPECT_NE(svg.find("<g class=\"lepp_path__2\" id=\"lepp_path__2\""), std::string::npos);
}

TEST(Svg, WhatIsOutOfViewIsLeftOutAndBordersKept) {
  Scene s = test_scene();
  Shape far;
  far.layer = Layer::overlay;
  far.kind = ShapeKind::triangles;
  far.role = "far";
  far.color = kRed;
  far.points = {{100, 100}, {101, 100}, {100, 101}};
  s.shapes.push_back(far);
  Shape crossing = far;
  crossing.role = "crossing";
  crossing.points = {{-1, 4}, {1, 4}, {0, 6}};  // half in the picture, across its left side
  s.shapes.push_back(crossing);
  const std::string svg = to_svg(s, test_camera());
  EXPECT_EQ(group(svg, "<g class=\"far\"").find("<path"), std::string::npos);
  const std::vector<std::string> d = attribute_values(group(svg, "<g class=\"crossing\""), "d");
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(polylines(d[0]).size(), 1u);
}

TEST(Svg, NonFiniteCoordinatesAreLeftOut) {
  Scene s = test_scene();
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  s.mesh.points.push_back({nan, 1});
  s.mesh.points.push_back({inf, 1});
  s.mesh.triangles.push_back({0, 5, 6});
  s.mesh.fill.push_back(kBlue);
  s.shapes[0].points.insert(s.shapes[0].points.end(), {{nan, 1}, {3, 3}});
  s.shapes[1].points.push_back({15, 5});
  s.shapes[1].radii.push_back(inf);
  s.labels.push_back({{nan, 0}, "lost", {255, 255, 255, 255}, 12.0f, 0.0f, 0.0f});
  const std::string svg = to_svg(s, test_camera());
  EXPECT_EQ(xml_problem(svg), "");
  for (const char* bad : {"nan", "inf", "lost"}) EXPECT_EQ(svg.find(bad), std::string::npos) << bad;
  // The edges of the triangle with the bad points are gone, the others all there.
  const std::vector<std::string> d = attribute_values(group(svg, "<g id=\"layer-edges\""), "d");
  std::size_t segments = 0;
  for (const std::string& path : d)
    for (const auto& line : polylines(path)) segments += line.size() - 1;
  EXPECT_EQ(segments, 7u);
}

TEST(Svg, HugeCirclesAreCutNearThePicture) {
  Scene s = test_scene();
  s.shapes[1].points = {{10, -1e9}};  // its top passes through y = 5, across the picture
  s.shapes[1].radii = {1e9 + 5};
  const std::string svg = to_svg(s, test_camera());
  const std::string circle = group(svg, "<g class=\"flip_circle\"");
  EXPECT_EQ(circle.find("<circle"), std::string::npos);
  // Every point of its path lies in the guard box (4096 px around the picture).
  const std::vector<std::string> d = attribute_values(circle, "d");
  ASSERT_EQ(d.size(), 1u);
  std::size_t points = 0;
  for (const auto& line : polylines(d[0]))
    for (const Point& p : line) {
      EXPECT_TRUE(std::abs(p.x - 100) <= 4096 + 100 + 0.01 && std::abs(p.y - 50) <= 4096 + 50 + 0.01) << p.x << ", " << p.y;
      ++points;
    }
  EXPECT_GE(points, 2u);
}

TEST(Svg, LargeMeshStaysCompact) {
  // 80,000 triangles on 1280 x 720: a few bytes per triangle, every one of them drawn.
  Scene s;
  const int n = 200;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) s.mesh.points.push_back({x + 0.3 * std::sin(x * 7.0 + y), y + 0.3 * std::cos(y * 5.0 + x)});
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const std::uint32_t a = static_cast<std::uint32_t>(y * (n + 1) + x), b = a + 1, c = a + n + 1, d = c + 1;
      s.mesh.triangles.push_back({a, b, d});
      s.mesh.triangles.push_back({a, d, c});
      s.mesh.fill.push_back(Rgba{static_cast<std::uint8_t>(x), 100, 100, 255});
      s.mesh.fill.push_back(Rgba{static_cast<std::uint8_t>(x), 100, 100, 255});
    }
  s.mesh.edge_color = {0, 0, 0, 255};
  s.bounds.add({0, 0});
  s.bounds.add({n, n});
  const std::string svg = to_svg(s, Camera::fit(s.bounds, 1280, 720));
  EXPECT_LT(svg.size(), 60u * s.mesh.triangles.size());
  const std::string fill = group(svg, "<g id=\"layer-fill\"");
  EXPECT_EQ(count(fill, "<path"), static_cast<std::size_t>(n));  // one per colour
  EXPECT_EQ(count(fill, "z"), s.mesh.triangles.size());
  EXPECT_EQ(xml_problem(svg), "");
}

// ---- pictures ----------------------------------------------------------------------------

// The picture rsvg-convert draws from the document.
Image render(const std::string& svg, TempDir& dir) {
  const std::string in = dir.write("scene.svg", svg), out = dir.file("scene.png");
  const std::string command = "rsvg-convert -o " + out + " " + in;
  if (std::system(command.c_str()) != 0) {
    ADD_FAILURE() << command << " failed";
    return {};
  }
  return read_png(out);
}

Rgba at(const Image& image, double x, double y) {
  const std::uint8_t* p = image.row(static_cast<int>(y)) + static_cast<std::size_t>(x) * 4;
  return {p[0], p[1], p[2], p[3]};
}

void expect_near(Rgba actual, Rgba expected, int tolerance, const char* what) {
  const int d = std::max({std::abs(actual.r - expected.r), std::abs(actual.g - expected.g), std::abs(actual.b - expected.b),
                          std::abs(actual.a - expected.a)});
  EXPECT_LE(d, tolerance) << what << ": got " << int{actual.r} << "," << int{actual.g} << "," << int{actual.b} << ","
                          << int{actual.a} << ", want " << int{expected.r} << "," << int{expected.g} << ","
                          << int{expected.b} << "," << int{expected.a};
}

TEST(SvgPicture, RsvgDrawsWhatTheSceneSays) {
  if (!have_program("rsvg-convert")) GTEST_SKIP() << "rsvg-convert not installed (apt-get install librsvg2-bin)";
  TempDir dir;
  const Camera camera = test_camera();
  const Image image = render(to_svg(test_scene(), camera), dir);
  ASSERT_EQ(image.width, 200);
  ASSERT_EQ(image.height, 100);
  const auto world = [&](double x, double y) { return camera.to_screen({x, y}); };
  expect_near(at(image, 1, 1), kBackground, 0, "top-left corner");
  expect_near(at(image, 198, 98), kBackground, 0, "bottom-right corner");
  // Each triangle's colour at its centroid (A and C red, B blue; y up in the world).
  const Point a = world(6, 4), b = world(4, 6), c = world(10, 4);
  expect_near(at(image, a.x, a.y), kRed, 1, "triangle A");
  expect_near(at(image, b.x, b.y), kBlue, 1, "triangle B");
  expect_near(at(image, c.x, c.y), kRed, 1, "triangle C");
  // The mesh edge between A and C (x = 8): a 1-px black line on a pixel border, over red,
  // covering half of the pixel on each side.
  const Point edge = world(8, 3);
  EXPECT_LT(at(image, edge.x - 1, edge.y).r, 150);
  EXPECT_LT(at(image, edge.x, edge.y).r, 150);
  EXPECT_GT(at(image, edge.x + 2, edge.y).r, 190);
  // The 4-px green line along y = 1, and the yellow circle's rightmost point.
  const Point on_line = world(10, 1);
  expect_near(at(image, on_line.x, on_line.y), kGreen, 1, "line");
  const Point rim = world(16.5, 5);
  expect_near(at(image, rim.x, rim.y), kYellow, 1, "circle");
  const Point inside = world(15, 5);
  expect_near(at(image, inside.x, inside.y), kBackground, 0, "inside the unfilled circle");
}

TEST(SvgPicture, NoSeamBetweenTrianglesOfDifferentColours) {
  if (!have_program("rsvg-convert")) GTEST_SKIP() << "rsvg-convert not installed (apt-get install librsvg2-bin)";
  // Two near-white triangles on black, edges off: along their shared diagonal no pixel may
  // let the black through (without the seam stroke, rsvg leaves it about 17% dark).
  Scene s;
  s.background = {0, 0, 0, 255};
  s.mesh.points = {{1.03, 1.07}, {9.02, 1.01}, {8.97, 9.04}, {1.01, 8.96}};
  s.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  s.mesh.fill = {{255, 255, 255, 255}, {250, 250, 250, 255}};
  s.visible.set(Layer::edges, false);
  const Camera camera({5, 5}, 10.0, 100, 100);
  TempDir dir;
  const Image image = render(to_svg(s, camera), dir);
  ASSERT_EQ(image.width, 100);
  int darkest = 255;
  for (int y = 20; y < 80; ++y)
    for (int x = 20; x < 80; ++x) darkest = std::min<int>(darkest, at(image, x, y).r);
  EXPECT_GE(darkest, 235);
}

TEST(SvgPicture, HugeCircleLandsWhereItShould) {
  if (!have_program("rsvg-convert")) GTEST_SKIP() << "rsvg-convert not installed (apt-get install librsvg2-bin)";
  // A circle of radius 1e9 whose top passes along y = 5: a horizontal yellow line through
  // the picture's middle, its (translucent green) inside below it.
  Scene s;
  s.background = kBackground;
  Shape circle;
  circle.kind = ShapeKind::circles;
  circle.color = kYellow;
  circle.fill = {0, 255, 0, 255};
  circle.width_px = 4.0f;
  circle.points = {{10, 5 - 1e9}};
  circle.radii = {1e9};
  s.shapes.push_back(circle);
  TempDir dir;
  const Camera camera = test_camera();
  const Image image = render(to_svg(s, camera), dir);
  ASSERT_EQ(image.width, 200);
  const Point on_rim = camera.to_screen({3, 5}), below = camera.to_screen({17, 2}), above = camera.to_screen({17, 8});
  expect_near(at(image, on_rim.x, on_rim.y), kYellow, 1, "rim");
  expect_near(at(image, below.x, below.y), Rgba{0, 255, 0, 255}, 1, "inside");
  expect_near(at(image, above.x, above.y), kBackground, 0, "outside");
}

}  // namespace
}  // namespace meshstep::scene
