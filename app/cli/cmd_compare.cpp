// meshstep compare: runs side by side. Two forms:
//   compare A.mslog B.mslog ...      recorded runs, their numbers at the end in columns
//   compare --algorithms A,B INPUT.. every algorithm (or recipe) on every input, a row each,
//                                    run here on a pool of threads (compare_matrix.hpp)
#include <sys/resource.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "command.hpp"
#include "compare_logs.hpp"
#include "compare_matrix.hpp"
#include "compare_matrix_report.hpp"
#include "compare_picture.hpp"
#include "console.hpp"
#include "draw_options.hpp"
#include "refuse_overwrites.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/atomic_file.hpp"
#include "meshstep/io/formats.hpp"
#include "meshstep/refine/registry.hpp"
#include "meshstep/refine/run_spec.hpp"
#include "recipe_file.hpp"

namespace meshstep::app {
namespace {

struct CompareArgs {
  std::vector<std::string> files;  // logs, or the inputs of --algorithms / --recipes
  std::string algorithms, recipes;
  // The bounds of every run, in refine's words (--min-angle may be a sweep).
  std::string min_angle, max_angle, max_aspect, max_area, size, max_steiner, max_triangles, ds, insertion;
  bool json = false, csv = false;
  std::string plot;
  std::string svg, png;  // logs side by side at one moment
  std::string video;     // ... or at every step
  double fps = 10.0;
  long long step = -2;   // -2: not given
  double fraction = -1;  // < 0: not given
  unsigned jobs = 2;
};

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> items;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    items.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return items;
}

// The process's peak resident memory, in bytes (Linux gives kilobytes).
std::size_t peak_rss_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<std::size_t>(usage.ru_maxrss) * 1024;
}

// ---------------------------------------------------------------------------------------
// compare A.mslog B.mslog ...

int compare_logs(const CompareArgs& args) {
  if (args.files.size() < 2) {
    print_error("compare: two logs or more to compare (or --algorithms A,B INPUT... to run them)");
    return kExitUsage;
  }
  if (args.csv || !args.plot.empty()) {
    print_error(std::string(args.csv ? "--csv" : "--plot") + " is for --algorithms or --recipes: logs compare as text or --json");
    return kExitUsage;
  }
  if (!args.svg.empty() + !args.png.empty() + !args.video.empty() > 1) {
    print_error("--svg, --png and --video: one picture at a time");
    return kExitUsage;
  }
  if ((args.step != -2 || args.fraction >= 0) && !args.video.empty()) {
    print_error("--step and --fraction choose a picture's moment; a --video shows every step");
    return kExitUsage;
  }
  const std::string picture = !args.svg.empty() ? args.svg : !args.png.empty() ? args.png : args.video;
  const std::string picture_option = !args.svg.empty() ? "--svg" : !args.png.empty() ? "--png" : "--video";
  if (args.step != -2 && args.fraction >= 0) {
    print_error("--step and --fraction: one moment or the other");
    return kExitUsage;
  }
  if ((args.step != -2 || args.fraction >= 0) && picture.empty()) {
    print_error("--step and --fraction choose the moment of a picture (--svg OUT or --png OUT)");
    return kExitUsage;
  }
  if (!args.svg.empty() && !args.svg.ends_with(".svg")) {
    print_error("--svg " + args.svg + ": the picture's name must end in .svg");
    return kExitUsage;
  }
  if (!args.png.empty() && !args.png.ends_with(".png")) {
    print_error("--png " + args.png + ": the picture's name must end in .png");
    return kExitUsage;
  }
  if (!picture.empty()) {
    FileRoles files;
    for (const std::string& log : args.files) files.reads(log);
    files.writes(picture_option, picture, args.video.empty() ? "picture" : "video");
    if (const int refused = refuse_overwrites(files)) return refused;
  }
  // Each log is checked in full (as log verify does): two at a time.
  std::vector<std::optional<LoggedRun>> read(args.files.size());
  std::vector<std::string> problems(args.files.size());
  {
    std::atomic<std::size_t> next{0};
    std::vector<std::jthread> pool;
    for (unsigned t = 0; t < std::max(args.jobs, 1u); ++t)
      pool.emplace_back([&] {
        for (std::size_t i = next++; i < args.files.size(); i = next++) {
          try {
            read[i] = read_logged_run(args.files[i]);
          } catch (const InputError& e) {
            problems[i] = e.what();
          } catch (const std::bad_alloc&) {
            problems[i] = args.files[i] + ": out of memory";
          }
        }
      });
  }
  for (const std::string& problem : problems)
    if (!problem.empty()) {
      print_error(problem);
      return kExitBadInput;
    }
  std::vector<LoggedRun> runs;
  for (auto& r : read) runs.push_back(std::move(*r));
  if (const std::string warning = different_inputs_warning(runs); !warning.empty())
    print_warning(Verbosity::normal, warning);

  if (!picture.empty()) {
    SideBySide side;
    for (const LoggedRun& r : runs) {
      side.logs.push_back(r.path);
      side.captions.push_back(r.caption);
    }
    if (args.step != -2) side.step = args.step;
    if (args.fraction >= 0) side.fraction = args.fraction;
    const int status = with_picture_errors(" (an .svg picture needs no OpenGL)", [&] {
      if (args.video.empty()) write_side_by_side(side, picture);
      else write_side_by_side_video(side, picture, args.fps);
      return kExitOk;
    });
    if (status != kExitOk) return status;
  }

  std::printf("%s", (args.json ? logs_json(runs) + "\n" : logs_text(runs)).c_str());
  return kExitOk;
}

// ---------------------------------------------------------------------------------------
// compare --algorithms A,B,... INPUT...

int build_matrix(const CompareArgs& args, Matrix& m) {
  if (args.files.empty()) {
    print_error("compare: no input (compare --algorithms A,B INPUT...)");
    return kExitUsage;
  }
  if (!args.algorithms.empty() && !args.recipes.empty()) {
    print_error("--algorithms and --recipes: one or the other");
    return kExitUsage;
  }
  // The bounds every algorithm runs to, as an operation of refine's (a recipe has its own).
  Operation base;
  const std::pair<const char*, const std::string*> bounds[] = {
      {"max-angle", &args.max_angle}, {"max-aspect", &args.max_aspect},     {"max-area", &args.max_area},
      {"size", &args.size},           {"max-steiner", &args.max_steiner}, {"max-triangles", &args.max_triangles},
      {"ds", &args.ds},               {"insertion", &args.insertion}};
  try {
    if (!args.min_angle.empty()) m.bounds = parse_sweep(args.min_angle);
    for (const auto& [name, value] : bounds)
      if (!value->empty()) set_option(base, name, *value);
  } catch (const RunSpecError& e) {
    print_error(e.what());
    return kExitUsage;
  }

  struct Entry {
    std::string label;
    std::vector<Operation> operations;
    std::vector<std::string> origins;
    std::string recipe;
  };
  std::vector<Entry> entries;
  if (!args.recipes.empty()) {
    const bool any_bound = !args.min_angle.empty() || !args.max_angle.empty() || !args.max_aspect.empty() ||
                           !args.max_area.empty() || !args.size.empty() || !args.max_steiner.empty() ||
                           !args.max_triangles.empty();
    if (any_bound) {
      print_error("--recipes: a recipe's lines give its bounds; the bound options are for --algorithms");
      return kExitUsage;
    }
    for (const std::string& path : split_list(args.recipes)) {
      std::optional<Recipe> recipe = read_recipe_file(path, args.ds, args.insertion);
      if (!recipe) return kExitBadInput;
      entries.push_back({std::filesystem::path(path).stem().string(), std::move(recipe->operations),
                         std::move(recipe->origins), path});
    }
  } else {
    for (const std::string& name : split_list(args.algorithms)) {
      if (!find_algorithm(name)) {
        std::string known;
        for (const AlgorithmInfo& a : algorithms()) known += (known.empty() ? "" : ", ") + std::string(a.name);
        print_error("--algorithms: unknown algorithm '" + name + "' (known: " + known + ")");
        return kExitUsage;
      }
      Operation op = base;
      op.algorithm = name;
      entries.push_back({name, {op}, {}, ""});
    }
  }
  for (const Entry& e : entries) {
    if (std::find(m.labels.begin(), m.labels.end(), e.label) != m.labels.end()) {
      print_error("compare: '" + e.label + "' is named twice");
      return kExitUsage;
    }
    m.labels.push_back(e.label);
  }
  // An input that is not there is said once, before any run.
  for (const std::string& input : args.files) {
    if (io::is_surface(input)) {
      print_error(input + ": compare refines planar inputs (.poly, .node or a mesh PREFIX), not a 3D surface");
      return kExitUsage;
    }
    if (std::filesystem::is_regular_file(input) && io::is_replay_log(input)) {
      print_error(input + ": a replay log is compared as it is, without --algorithms or --recipes (those run inputs)");
      return kExitUsage;
    }
    if (io::is_planar_input(input) ? !std::ifstream(input).good() : !std::ifstream(input + ".node").good()) {
      print_error(io::is_planar_input(input) ? input + ": cannot be read"
                                             : input + ": neither a .poly or .node file nor a mesh PREFIX (no " +
                                                   input + ".node)");
      return kExitBadInput;
    }
  }
  // Rows: by input, then bound, then algorithm, so that an input's algorithms stand together.
  const std::vector<double> sweep = m.bounds.empty() ? std::vector<double>{std::nan("")} : m.bounds;
  for (const std::string& input : args.files)
    for (const double bound : sweep)
      for (const Entry& e : entries) {
        MatrixRun run{e.label, input, bound, e.operations, e.origins, e.recipe};
        if (!std::isnan(bound)) {
          try {
            for (Operation& op : run.operations) set_option(op, "min-angle", bound_text(bound));
          } catch (const RunSpecError& err) {
            print_error(err.what());
            return kExitUsage;
          }
        }
        m.runs.push_back(std::move(run));
      }
  return kExitOk;
}

int compare_algorithms(const CompareArgs& args) {
  if (args.json && args.csv) {
    print_error("--json and --csv: one or the other");
    return kExitUsage;
  }
  Matrix m;
  if (const int status = build_matrix(args, m)) return status;
  if (!args.plot.empty()) {
    FileRoles files;
    for (const std::string& input : args.files) files.reads_pslg(input);
    if (!args.recipes.empty())
      for (const std::string& r : split_list(args.recipes)) files.reads(r);
    files.writes("--plot", args.plot, "plot file");
    if (const int refused = refuse_overwrites(files)) return refused;
  }

  const std::vector<MatrixRow> rows = run_matrix(m.runs, args.jobs);
  std::size_t failed = 0;
  for (const MatrixRow& row : rows) failed += row.status != kExitOk;
  if (failed) {
    print_error(std::to_string(failed) + " of " + std::to_string(rows.size()) +
                " runs failed (their errors are above): no table");
    return kExitBadInput;
  }
  const MatrixSummary summary = summarize(m, rows, peak_rss_bytes(), std::max(args.jobs, 1u));

  // The plot first: a plot that cannot be written fails the command before anything is printed.
  if (!args.plot.empty()) {
    try {
      io::write_file_atomically(args.plot, matrix_plot_svg(m, rows, args.files.size()));
    } catch (const InputError& e) {
      print_error(e.what());
      return kExitBadInput;
    }
  }
  if (args.json) std::printf("%s\n", matrix_json(m, rows, summary).c_str());
  else if (args.csv) std::printf("%s", matrix_table(m, rows, true).c_str());
  else std::printf("%s\n%s", matrix_table(m, rows, false).c_str(), matrix_summary_text(m, summary).c_str());
  return kExitOk;
}

int run_compare(const CompareArgs& args) {
  if (!args.algorithms.empty() || !args.recipes.empty()) return compare_algorithms(args);
  const bool bound_given = !args.min_angle.empty() || !args.max_angle.empty() || !args.max_aspect.empty() ||
                           !args.max_area.empty() || !args.size.empty() || !args.max_steiner.empty() ||
                           !args.max_triangles.empty() || !args.ds.empty() || !args.insertion.empty();
  if (bound_given) {
    print_error("compare: bounds and parts are for --algorithms or --recipes (logs were run with their own)");
    return kExitUsage;
  }
  return compare_logs(args);
}

}  // namespace

Command add_compare_command(CLI::App& parent) {
  auto args = std::make_shared<CompareArgs>();
  CLI::App* cmd = parent.add_subcommand(
      "compare",
      "Compare runs side by side. With logs (compare A.mslog B.mslog ...): each run's\n"
      "description, Steiner points, triangles, smallest and largest angle and steps per phase,\n"
      "a column per run (each log is checked as 'log verify' checks it). With --algorithms\n"
      "A,B,... (or --recipes R1,R2) and inputs: every algorithm on every input, run here two at\n"
      "a time, a row each, and the Steiner points of each algorithm relative to the first\n"
      "(docs/compare.md).");
  cmd->add_option("FILES", args->files, "Replay logs; or, with --algorithms or --recipes, the inputs (.poly, .node, mesh PREFIX)")
      ->required();
  cmd->add_option("--algorithms", args->algorithms, "Comma-separated algorithms to run on every input (meshstep list)")
      ->type_name("A,B,...");
  cmd->add_option("--recipes", args->recipes, "Comma-separated recipe files to run on every input (as meshstep run)")
      ->type_name("R1,R2,...");
  cmd->add_option("--min-angle", args->min_angle, "Angle bound of every run, or a sweep START:END:STEP (20:34:2)")
      ->type_name("DEG|A:B:S");
  cmd->add_option("--max-angle", args->max_angle, "As refine's")->type_name("DEG");
  cmd->add_option("--max-aspect", args->max_aspect, "As refine's")->type_name("R");
  cmd->add_option("--max-area", args->max_area, "As refine's")->type_name("AREA");
  cmd->add_option("--size", args->size, "As refine's")->type_name("LENGTH|GRID");
  cmd->add_option("--max-steiner", args->max_steiner, "As refine's")->type_name("N");
  cmd->add_option("--max-triangles", args->max_triangles, "As refine's")->type_name("N");
  cmd->add_option("--ds", args->ds, "Mesh data structure of every run: tds or dcel");
  cmd->add_option("--insertion", args->insertion, "Point insertion of every run: flip, cavity or bisection");
  cmd->add_flag("--json", args->json, "One JSON object instead of text");
  cmd->add_flag("--csv", args->csv, "--algorithms, --recipes: CSV instead of text, one line per run");
  cmd->add_option("--plot", args->plot,
                  "Write an SVG figure: the distribution of the triangles' smallest angles per\n"
                  "algorithm, and with a --min-angle sweep, Steiner points against the bound")
      ->type_name("OUT.svg");
  cmd->add_option("--svg", args->svg, "Logs: draw the runs side by side at one moment, one scale for all (no display needed)")
      ->type_name("OUT.svg");
  cmd->add_option("--png", args->png, "Logs: the same picture as PNG (drawn by OpenGL, off screen)")->type_name("OUT.png");
  cmd->add_option("--video", args->video,
                  "Logs: the runs side by side as a video, one frame per step of the longest run\n"
                  "(.mp4, .webm or .gif; needs ffmpeg and OpenGL)")
      ->type_name("OUT.mp4");
  cmd->add_option("--fps", args->fps, "The video's frames per second (default 10)");
  cmd->add_option("--step", args->step, "The picture's moment: after K steps of each run (-1: the end, the default)")
      ->type_name("K");
  cmd->add_option("--fraction", args->fraction, "The picture's moment: at this fraction (0 to 1) of each run's steps")
      ->type_name("F");
  cmd->add_option("-j,--jobs", args->jobs, "Runs at a time (default 2)")->check(CLI::Range(1u, 256u));
  cmd->footer(
      "Examples:\n"
      "  meshstep compare circumcenter.mslog offcenter.mslog --json\n"
      "  meshstep compare circumcenter.mslog offcenter.mslog --fraction 0.5 --svg half.svg\n"
      "  meshstep compare --algorithms offcenter,circumcenter,lepp-centroid --min-angle 20:34:2 \\\n"
      "      assets/examples/lesson.poly assets/examples/plate.poly --plot sweep.svg\n"
      "Exit status: 0 done, 1 a log that is damaged (in log verify's words) or an input that\n"
      "cannot be read or run, 2 usage error (an unknown algorithm, a bad sweep).");
  return {cmd, [args] { return run_compare(*args); }};
}

}  // namespace meshstep::app
