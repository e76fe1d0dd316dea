// meshstep render: one picture (PNG or SVG) of a moment of a run, a mesh or an input.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <memory>
#include <string>

#include "command.hpp"
#include "console.hpp"
#include "draw_options.hpp"
#include "refuse_overwrites.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/atomic_file.hpp"
#include "meshstep/io/surface_io.hpp"
#include "meshstep/replay/step_numbers.hpp"
#include "meshstep/scene/layout.hpp"
#include "meshstep/scene/lift.hpp"
#include "meshstep/scene/surface_view.hpp"
#include "meshstep/scene/svg.hpp"
#include "moment_scene.hpp"
#include "orbit_options.hpp"
#include "common/output_prefix.hpp"
#include "common/scene_source.hpp"
#include "render/painter.hpp"

namespace meshstep::app {
namespace {

struct RenderArgs {
  std::string input;
  std::string output;
  std::int64_t step = -2;   // -2: not given
  std::int64_t event = -2;
  DrawArgs draw;
  OrbitArgs orbit;
  bool quiet = false;
};

enum class Format { png, svg };

Format format_of(const std::string& path) {
  if (path.ends_with(".png")) return Format::png;
  if (path.ends_with(".svg")) return Format::svg;
  throw UsageError("-o " + path + ": the picture's name must end in .png or .svg");
}

// A surface in 3D: the input's extension is that of a surface format (.obj .off .ply .stl).
bool is_surface(const std::string& path) { return io::surface_format_for(path).has_value(); }

// The mesh PREFIX that INPUT names when it is neither a log, an input, nor a surface (as
// open_scene_source reads it): INPUT, or INPUT without its .ele.
std::string mesh_prefix_of(const std::string& input) {
  return input.ends_with(".ele") ? strip_extension(input) : input;
}

// INPUT without its extension, plus .png; a mesh prefix keeps its whole name (box.1 ->
// box.1.png).
std::string default_output(const std::string& input) {
  const bool named_by_extension = is_surface(input) || input.ends_with(".poly") || input.ends_with(".node") ||
                                  (std::filesystem::is_regular_file(input) && is_replay_log(input));
  return (named_by_extension ? strip_extension(input) : mesh_prefix_of(input)) + ".png";
}

// The replay position the options ask for, checked against the run.
std::uint64_t position_of(const RenderArgs& args, const replay::LogReader& log) {
  if (args.step != -2 && args.event != -2) throw UsageError("give --step or --event, not both");
  if (args.event != -2) {
    if (args.event < -1 || (args.event >= 0 && static_cast<std::uint64_t>(args.event) > log.event_count()))
      throw UsageError(log.path() + ": --event " + std::to_string(args.event) + " is out of range: the run has " +
                       std::to_string(log.event_count()) + " events (use 0.." + std::to_string(log.event_count()) +
                       ", or -1 for the end)");
    return args.event < 0 ? log.event_count() : static_cast<std::uint64_t>(args.event);
  }
  if (args.step != -2) {
    if (const std::string refused = replay::step_refusal(log, "--step", args.step); !refused.empty())
      throw UsageError(refused);
    return args.step < 0 ? log.event_count() : replay::step_position(log, static_cast<std::uint64_t>(args.step));
  }
  return log.event_count();
}

// Writes the picture of `scene` as the output's extension says; returns how it was drawn.
std::string write_picture(const std::string& output, const scene::Scene& picture, const DrawSettings& draw) {
  const scene::Camera camera =
      draw.view ? draw.camera(picture.bounds) : scene::fit_scene(picture, draw.width, draw.height);
  if (format_of(output) == Format::svg) {
    io::write_file_atomically(output, scene::to_svg(picture, camera));
    return "SVG";
  }
  render::Painter painter(draw.gl);
  scene::write_png(output, painter.paint(picture, camera, draw.samples));
  return "PNG, " + painter.description();
}

// A triangle surface seen from an orbit camera (scene/surface_view.hpp). Surfaces are
// always coloured by height: --color-by height (or none) is accepted, any other refused.
int render_surface(const RenderArgs& args, Verbosity verbosity) {
  DrawArgs draw_args = args.draw;
  if (draw_args.color_by != "none" && draw_args.color_by != "height")
    throw UsageError("--color-by " + draw_args.color_by + ": a 3D surface is coloured by height (use height or none)");
  draw_args.color_by = "none";
  const DrawSettings draw = parse_draw_args(draw_args);
  if (args.step != -2 || args.event != -2) throw UsageError("--step and --event need a replay log; " + args.input + " is a surface");
  const scene::SurfaceView view = surface_view_of(args.orbit);
  const std::string output = args.output.empty() ? default_output(args.input) : args.output;
  format_of(output);

  const io::Surface surface = io::read_surface(args.input);
  const std::string name = std::filesystem::path(args.input).filename().string();
  scene::Scene picture = scene::surface_scene(surface, view, draw.scene.theme, name);
  picture.visible = draw.scene.layers;
  const std::string how = write_picture(output, picture, draw);
  if (verbosity != Verbosity::quiet)
    std::printf("%s: %dx%d picture of %s in 3D (%zu triangles; %s)\n", output.c_str(), draw.width, draw.height,
                args.input.c_str(), picture.mesh.triangles.size(), how.c_str());
  return kExitOk;
}

int run_render(const RenderArgs& args) {
  const Verbosity verbosity = args.quiet ? Verbosity::quiet : Verbosity::normal;
  const int refused = refuse_overwrites(FileRoles()
                                            .reads_pslg(args.input)
                                            .reads_mesh(mesh_prefix_of(args.input))
                                            .writes(args.output.empty() ? "" : "-o",
                                                    args.output.empty() ? default_output(args.input) : args.output,
                                                    "picture"));
  if (refused) return refused;
  return with_picture_errors(" (an .svg picture needs no OpenGL)", [&] {
    const bool surface = is_surface(args.input);
    if (surface) return render_surface(args, verbosity);
    const bool in_3d = args.orbit.given();
    const DrawSettings draw = parse_draw_args(args.draw);
    if (!args.output.empty()) format_of(args.output);
    std::vector<std::string> warnings;
    SceneSource source = open_scene_source(args.input, &warnings);
    for (const std::string& w : warnings) print_warning(verbosity, w);
    if (in_3d && !(source.kind == SourceKind::log && source.log->has_elevation()))
      throw UsageError(args.orbit.name() +
                       " needs a 3D surface (.obj, .off, .ply or .stl) or a terrain's replay log (meshstep terrain "
                       "--record); " + args.input + " is neither");
    if (source.kind != SourceKind::log && (args.step != -2 || args.event != -2))
      throw UsageError("--step and --event need a replay log; " + args.input + " is " +
                       (source.kind == SourceKind::mesh ? "a mesh" : "an input"));
    const std::string output = args.output.empty() ? default_output(args.input) : args.output;
    const Format format = format_of(output);

    scene::Scene picture;
    std::string moment;
    if (source.kind == SourceKind::log) {
      const std::uint64_t position = position_of(args, *source.log);
      scene::SceneOptions scene_options = draw.scene;
      // A surface seen at a slant packs its vertices closer: a quarter as many markers.
      if (in_3d) scene_options.max_vertex_markers /= 4;
      LogScenes scenes(*source.log, scene_options);
      // A terrain's moment in 3D: the same step, lifted onto its surface (scene/lift.hpp).
      picture = in_3d ? scenes.at(position, surface_view_of(args.orbit)) : scenes.at(position);
      moment = " at step " + std::to_string(scenes.cursor().completed_steps()) + " of " +
               std::to_string(source.log->step_count()) + " (event " + std::to_string(position) + ")";
    } else if (source.kind == SourceKind::mesh) {
      picture = scene::build_scene(*source.mesh, draw.scene);
    } else {
      picture = scene::build_scene(*source.input, draw.scene);
    }
    const scene::Camera camera =
        draw.view ? draw.camera(picture.bounds) : scene::fit_scene(picture, draw.width, draw.height);

    std::string how;
    if (format == Format::svg) {
      io::write_file_atomically(output, scene::to_svg(picture, camera));
      how = "SVG";
    } else {
      render::Painter painter(draw.gl);
      scene::write_png(output, painter.paint(picture, camera, draw.samples));
      how = "PNG, " + painter.description();
    }
    if (verbosity != Verbosity::quiet)
      std::printf("%s: %dx%d picture of %s%s (%zu triangles; %s)\n", output.c_str(), draw.width, draw.height,
                  args.input.c_str(), moment.c_str(), picture.mesh.triangles.size(), how.c_str());
    return kExitOk;
  });
}

}  // namespace

Command add_render_command(CLI::App& parent) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = parent.add_subcommand(
      "render",
      "Draw one picture, PNG (off screen, through OpenGL) or SVG (no OpenGL needed), of:\n"
      "  a replay log (--record): the mesh at any moment of the run, with overlays that explain\n"
      "    the step just taken (default: the end of the run);\n"
      "  a mesh PREFIX (PREFIX.node + PREFIX.ele);\n"
      "  an input .poly or .node, before triangulation;\n"
      "  a triangle surface .obj, .off, .ply or .stl (a terrain TIN, say) in 3D: an orbit camera\n"
      "    (parallel projection), lit faces coloured by height, a wireframe (--orbit, --z-scale);\n"
      "  a terrain run's log (meshstep terrain --record) in 3D as well, with --orbit or --z-scale:\n"
      "    the step's overlays (the worst triangle, its Lepp path, the next sample) on the surface.");
  cmd->add_option("INPUT", args->input, "Replay log, mesh prefix, .poly/.node input, or .obj/.off/.ply/.stl surface")
      ->required();
  cmd->add_option("-o,--output", args->output,
                  "OUT.png or OUT.svg (default: INPUT without its extension, plus .png)");
  cmd->add_option("--step", args->step, "The moment after K steps (0: before the first; -1: the end)");
  cmd->add_option("--event", args->event, "The moment after N events (-1: the end)");
  add_orbit_options(*cmd, args->orbit, "Surfaces and terrain logs");
  add_draw_options(cmd, args->draw);
  cmd->add_flag("-q,--quiet", args->quiet, "Print only errors");
  cmd->footer(
      "A surface is always coloured by height: --color-by height (or none); any other value is refused.\n"
      "Examples:\n"
      "  meshstep refine assets/examples/lesson.poly --algorithm offcenter --min-angle 30 --record l.mslog\n"
      "  meshstep render l.mslog --step 40 -o step40.png\n"
      "  meshstep render l.mslog --color-by quality --theme dark -o end.png\n"
      "  meshstep render l.mslog --step 40 --layers -caption,-legend -o figure.svg\n"
      "  meshstep terrain dem.asc -o tin.obj && meshstep render tin.obj --orbit 30,40 --z-scale 2 -o tin.png");
  return {cmd, [args] { return run_render(*args); }};
}

}  // namespace meshstep::app
