// Reading a tour and resolving its stops against a run's log (teach/tour.hpp, docs/tours.md).
#include "meshstep/teach/tour.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "meshstep/error.hpp"
#include "meshstep/replay/event.hpp"

namespace meshstep::teach {
namespace {

namespace fs = std::filesystem;

constexpr std::array<const char*, kHappeningCount> kHappeningWords = {
    "segment-split", "encroached", "rejected", "flip", "lepp", "refine", "insert", "recover", "carve"};
// What a message says a step that does it is ("no segment split after step 12").
constexpr std::array<const char*, kHappeningCount> kHappeningPhrases = {
    "segment split",          "encroached segment",    "point rejected for encroaching",
    "Delaunay flip",          "Lepp path",             "refinement step",
    "input vertex inserted",  "segment recovered",     "carving step"};

std::string trimmed(std::string_view s) {
  const std::size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string_view::npos) return "";
  return std::string(s.substr(b, s.find_last_not_of(" \t\r") - b + 1));
}

std::vector<std::string> split_words(std::string_view s) {
  std::vector<std::string> words;
  std::istringstream in{std::string(s)};
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

std::optional<double> number(std::string_view s) {
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::optional<std::uint64_t> count(std::string_view s) {
  std::uint64_t v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || s.empty()) return std::nullopt;
  return v;
}

std::string layer_names() {
  std::string out;
  for (std::size_t i = 0; i < scene::kLayerCount; ++i) out.append(i ? ", " : "").append(scene::name(static_cast<scene::Layer>(i)));
  return out;
}

std::string happening_names() {
  std::string out;
  for (std::size_t i = 0; i < kHappeningCount; ++i) out.append(i ? ", " : "").append(kHappeningWords[i]);
  return out;
}

// "layers +labels -fill" (changes) or "layers fill edges segments" (exactly these).
LayerChoice parse_layers(const std::vector<std::string>& words, const std::string& path, int line) {
  if (words.empty()) throw InputError(path, line, "layers: expected +LAYER, -LAYER or the layers to show (" + layer_names() + ")");
  LayerChoice choice;
  bool signed_words = false, bare_words = false;
  for (const std::string& w : words) {
    const bool sign = w[0] == '+' || w[0] == '-';
    (sign ? signed_words : bare_words) = true;
    const std::optional<scene::Layer> layer = scene::parse_layer(sign ? std::string_view(w).substr(1) : std::string_view(w));
    if (!layer) throw InputError(path, line, "layers: unknown layer '" + w + "' (" + layer_names() + ")");
    choice.changes.emplace_back(*layer, !(sign && w[0] == '-'));
  }
  if (signed_words && bare_words)
    throw InputError(path, line, "layers: either changes (+labels -fill) or the layers to show (fill edges), not both");
  choice.exact = bare_words;
  return choice;
}

scene::ColorBy parse_colouring(const std::vector<std::string>& words, const std::string& path, int line) {
  if (words.size() == 1)
    if (const auto c = scene::parse_color_by(words[0])) return *c;
  throw InputError(path, line, "color-by: expected one of none, angle, quality, area, region, age, height");
}

CameraBox parse_camera(const std::vector<std::string>& words, const std::string& path, int line) {
  std::array<double, 4> v{};
  if (words.size() != 4) throw InputError(path, line, "camera: expected X0 Y0 X1 Y1 (the world box to show)");
  for (std::size_t i = 0; i < 4; ++i) {
    const auto n = number(words[i]);
    if (!n) throw InputError(path, line, "camera: '" + words[i] + "' is not a number");
    v[i] = *n;
  }
  if (!(v[2] > v[0] && v[3] > v[1]))
    throw InputError(path, line, "camera: the box's second corner must be right of and above its first (X1 > X0, Y1 > Y0)");
  return {v[0], v[1], v[2], v[3]};
}

double parse_hold(const std::vector<std::string>& words, const std::string& path, int line) {
  if (words.size() == 1)
    if (const auto n = number(words[0]); n && *n > 0.0 && *n <= kMaxHoldSeconds) return *n;
  throw InputError(path, line, "hold: expected seconds above 0 and at most 60");
}

void check_caption(const std::string& caption, const std::string& path, int line) {
  if (caption.size() > kMaxCaptionChars)
    throw InputError(path, line,
                     "caption: " + std::to_string(caption.size()) + " characters; at most " +
                         std::to_string(kMaxCaptionChars) + " (one to three sentences, read aloud in a breath or two)");
  const char last = caption.empty() ? ' ' : caption.back();
  if (last != '.' && last != '!' && last != '?') throw InputError(path, line, "caption: end it with '.', '!' or '?'");
  const std::size_t n = count_sentences(caption);
  if (n > 3) throw InputError(path, line, "caption: " + std::to_string(n) + " sentences; a stop says one to three");
}

TourStop parse_stop_place(const std::vector<std::string>& words, const std::string& path, int line) {
  TourStop stop;
  stop.line = line;
  const std::string usage = "stop: expected 'stop step K', 'stop start', 'stop end' or 'stop next KIND' (" +
                            happening_names() + ")";
  if (words.empty()) throw InputError(path, line, usage);
  if (words[0] == "start" && words.size() == 1) return stop;  // step 0
  if (words[0] == "end" && words.size() == 1) {
    stop.where = TourStop::Where::end;
    return stop;
  }
  if (words[0] == "step" && words.size() == 2) {
    const auto k = count(words[1]);
    if (!k) throw InputError(path, line, "stop step: '" + words[1] + "' is not a step number (0, 1, 2...)");
    stop.step = *k;
    return stop;
  }
  if (words[0] == "next" && words.size() >= 2) {
    std::string kind;
    for (std::size_t i = 1; i < words.size(); ++i) kind.append(i > 1 ? " " : "").append(words[i]);
    const auto h = parse_happening(kind);
    if (!h) throw InputError(path, line, "stop next: unknown kind '" + kind + "' (" + happening_names() + ")");
    stop.where = TourStop::Where::next;
    stop.next = *h;
    return stop;
  }
  throw InputError(path, line, usage);
}

// A recipe's operations (docs/recipes.md): one 'refine ...' a line, '#' starts a comment.
std::vector<Operation> read_recipe(const std::string& recipe, const std::string& tour, int tour_line) {
  std::ifstream in(recipe);
  if (!in) throw InputError(tour, tour_line, "recipe: " + recipe + " cannot be read");
  std::vector<Operation> ops;
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    const std::string words = trimmed(std::string_view(text).substr(0, text.find('#')));
    if (words.empty()) continue;
    try {
      Operation op = parse_operation(words);
      if (op.kind != OperationKind::refine) throw RunSpecError("a recipe's operations refine the mesh: 'refine ...' expected");
      ops.push_back(std::move(op));
    } catch (const RunSpecError& e) {
      throw InputError(recipe, static_cast<std::size_t>(line), e.what());
    }
  }
  if (ops.empty()) throw InputError(recipe, 0, "no operation in the recipe (one 'refine ...' line at least)");
  return ops;
}

std::string resolved(const std::string& tour, const std::string& relative) {
  const fs::path p(relative);
  if (p.is_absolute()) return p.string();
  return (fs::path(tour).parent_path() / p).lexically_normal().string();
}

}  // namespace

const char* name(Happening h) { return kHappeningWords[static_cast<std::size_t>(h)]; }

std::optional<Happening> parse_happening(std::string_view words) {
  std::string dashed(words);
  std::replace(dashed.begin(), dashed.end(), ' ', '-');
  for (std::size_t i = 0; i < kHappeningCount; ++i)
    if (dashed == kHappeningWords[i]) return static_cast<Happening>(i);
  // The singular spoken forms a lecturer may write.
  if (dashed == "split") return Happening::segment_split;
  if (dashed == "lepp-path") return Happening::lepp;
  return std::nullopt;
}

scene::LayerSet LayerChoice::apply(scene::LayerSet from) const {
  scene::LayerSet out = exact ? scene::LayerSet::none() : from;
  for (const auto& [layer, on] : changes) out.set(layer, on);
  return out;
}

std::size_t count_sentences(std::string_view caption) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < caption.size(); ++i) {
    const char c = caption[i];
    if (c != '.' && c != '!' && c != '?') continue;
    // "..." or "?!" end one sentence: count the last mark of a run.
    const bool last_mark = i + 1 == caption.size() || caption[i + 1] == ' ' || caption[i + 1] == '\t';
    if (last_mark) ++n;
  }
  return n;
}

Tour parse_tour(std::string_view text, const std::string& path) {
  Tour tour;
  tour.path = path;
  int input_line = 0;
  bool have_run = false;
  TourStop* stop = nullptr;
  int caption_line = 0;  // the current stop's last caption line
  std::istringstream in{std::string(text)};
  std::string raw;
  for (int line = 1; std::getline(in, raw); ++line) {
    // A caption may hold '#' only as text: comments are whole lines, or after a blank.
    std::string_view view(raw);
    if (const std::size_t hash = raw.find(" #"); hash != std::string::npos) view = view.substr(0, hash);
    const std::string body = trimmed(view);
    if (body.empty() || body[0] == '#') continue;
    const std::size_t space = body.find_first_of(" \t");
    const std::string key = body.substr(0, space);
    const std::string rest = space == std::string::npos ? "" : trimmed(std::string_view(body).substr(space));
    const std::vector<std::string> words = split_words(rest);
    const auto once = [&](bool already) {
      if (already) throw InputError(path, line, key + ": given twice");
      if (stop) throw InputError(path, line, key + ": belongs before the first stop (it says what the whole tour runs)");
    };
    if (key == "title") {
      once(!tour.title.empty());
      if (rest.empty()) throw InputError(path, line, "title: expected the tour's title");
      tour.title = rest;
    } else if (key == "input") {
      once(input_line != 0);
      if (rest.empty()) throw InputError(path, line, "input: expected the input file (.poly or .node), relative to the tour");
      tour.input = resolved(path, rest);
      input_line = line;
      std::error_code ec;
      if (!fs::is_regular_file(tour.input, ec)) throw InputError(path, line, "input: " + tour.input + " does not exist");
    } else if (key == "run") {
      once(have_run);
      have_run = true;
      tour.run_line = line;
      try {
        Operation op = parse_operation(words);
        // "run triangulate" alone: no operation, the triangulation is the run.
        if (!(op.kind == OperationKind::triangulate && words.size() == 1)) tour.operations.push_back(std::move(op));
      } catch (const RunSpecError& e) {
        throw InputError(path, line, std::string("run: ") + e.what());
      }
    } else if (key == "recipe") {
      once(have_run);
      have_run = true;
      tour.run_line = line;
      if (rest.empty()) throw InputError(path, line, "recipe: expected a recipe file, relative to the tour");
      tour.recipe = resolved(path, rest);
      tour.operations = read_recipe(tour.recipe, path, line);
    } else if (key == "stop") {
      if (input_line == 0) throw InputError(path, line, "stop: name the input first ('input FILE.poly')");
      if (!have_run) throw InputError(path, line, "stop: name the run first ('run refine ...', 'run triangulate' or 'recipe FILE')");
      if (stop && stop->caption.empty()) throw InputError(path, stop->line, "stop: no caption (say what the stop shows)");
      if (stop) check_caption(stop->caption, path, caption_line);
      tour.stops.push_back(parse_stop_place(words, path, line));
      stop = &tour.stops.back();
    } else if (key == "caption") {
      if (!stop) throw InputError(path, line, "caption: belongs to a stop ('stop ...' first)");
      if (rest.empty()) throw InputError(path, line, "caption: expected one to three sentences");
      // Several caption lines make one caption, checked whole when its stop ends.
      stop->caption.append(stop->caption.empty() ? "" : " ").append(rest);
      caption_line = line;
    } else if (key == "layers") {
      LayerChoice choice = parse_layers(words, path, line);
      (stop ? stop->layers : tour.layers) = std::move(choice);
    } else if (key == "color-by") {
      const scene::ColorBy c = parse_colouring(words, path, line);
      (stop ? stop->color_by : tour.color_by) = c;
    } else if (key == "camera") {
      if (!stop) throw InputError(path, line, "camera: belongs to a stop (the tour's camera is the whole run)");
      stop->camera = parse_camera(words, path, line);
    } else if (key == "hold") {
      const double s = parse_hold(words, path, line);
      if (stop) stop->hold_seconds = s;
      else tour.hold_seconds = s;
    } else {
      throw InputError(path, line,
                       "unknown line '" + key + "' (title, input, run, recipe, stop, caption, layers, color-by, camera, hold)");
    }
  }
  if (input_line == 0) throw InputError(path, 0, "no 'input FILE' line: a tour names its input");
  if (!have_run) throw InputError(path, 0, "no 'run ...' or 'recipe FILE' line: a tour names its run");
  if (tour.stops.empty()) throw InputError(path, 0, "no stop: a tour has at least one ('stop step K', then its caption)");
  if (stop && stop->caption.empty()) throw InputError(path, stop->line, "stop: no caption (say what the stop shows)");
  if (stop) check_caption(stop->caption, path, caption_line);
  return tour;
}

Tour read_tour(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path, 0, "cannot be read");
  return parse_tour(text.str(), path);
}

StepHappenings step_happenings(const replay::LogReader& log) {
  using replay::EventType;
  StepHappenings out;
  const std::uint64_t n = log.step_count();
  out.steps.assign(n, 0);
  const auto mark = [&](std::uint64_t step_index, Happening h) {
    out.steps[step_index] |= static_cast<std::uint16_t>(1u << static_cast<unsigned>(h));
  };
  for (std::uint64_t k = 0; k < n; ++k) {
    switch (log.step_kind(k)) {
      case replay::StepKind::refine: mark(k, Happening::refine); break;
      case replay::StepKind::insert_vertex: mark(k, Happening::insert); break;
      case replay::StepKind::recover_segment: mark(k, Happening::recover); break;
      case replay::StepKind::carve: mark(k, Happening::carve); break;
      case replay::StepKind::split_segment: mark(k, Happening::segment_split); break;
      default: break;
    }
  }
  for (std::uint64_t e = n ? log.step_start(0) : log.event_count(); e < log.event_count(); ++e) {
    const replay::Event ev = log.event(e);
    const std::uint64_t k = log.step_of_event(e);
    if (k >= n) continue;
    switch (ev.type) {
      case EventType::split_edge:
        if (ev.code == static_cast<std::uint8_t>(replay::SplitReason::encroached)) mark(k, Happening::segment_split);
        break;
      case EventType::encroached:
        mark(k, ev.ids[2] == kNone ? Happening::rejected : Happening::encroached);
        if (ev.ids[2] == kNone) mark(k, Happening::encroached);
        break;
      case EventType::flip:
        if (ev.code == static_cast<std::uint8_t>(replay::FlipReason::delaunay)) mark(k, Happening::flip);
        break;
      case EventType::lepp_path: mark(k, Happening::lepp); break;
      default: break;
    }
  }
  return out;
}

std::vector<std::uint64_t> resolve_stops(const Tour& tour, const replay::LogReader& log) {
  const std::uint64_t n = log.step_count();
  std::optional<StepHappenings> happenings;  // scanned once, when a rule needs it
  std::vector<std::uint64_t> steps;
  std::uint64_t previous = 0;
  for (const TourStop& stop : tour.stops) {
    std::uint64_t k = 0;
    switch (stop.where) {
      case TourStop::Where::step:
        if (stop.step > n)
          throw InputError(tour.path, static_cast<std::size_t>(stop.line),
                           "stop step " + std::to_string(stop.step) + " is outside the run: its steps are numbered 0.." +
                               std::to_string(n) + " (0: before the first step, " + std::to_string(n) + ": after the last)");
        k = stop.step;
        break;
      case TourStop::Where::end: k = n; break;
      case TourStop::Where::next: {
        if (!happenings) happenings = step_happenings(log);
        k = previous + 1;
        while (k <= n && !happenings->has(k, stop.next)) ++k;
        if (k > n)
          throw InputError(tour.path, static_cast<std::size_t>(stop.line),
                           std::string("stop next ") + name(stop.next) + ": no " +
                               kHappeningPhrases[static_cast<std::size_t>(stop.next)] + " after step " +
                               std::to_string(previous) + " (the run has " + std::to_string(n) + " steps)");
        break;
      }
    }
    steps.push_back(k);
    previous = k;
  }
  return steps;
}

}  // namespace meshstep::teach
