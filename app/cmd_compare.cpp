// meshstep compare: runs side by side. Two forms:
//   compare A.mslog B.mslog ...      recorded runs, their numbers at the end in columns
//   compare --algorithms A,B INPUT.. every algorithm (or recipe) on every input, a row each,
//                                    run here on a pool of threads (compare_matrix.hpp)
#include <sys/resource.h>

#include <algorithm>
#include <charconv>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "command.hpp"
#include "compare_logs.hpp"
#include "compare_matrix.hpp"
#include "compare_picture.hpp"
#include "draw_options.hpp"
#include "compare_table.hpp"
#include "console.hpp"
#include "file_roles.hpp"
#include "json_line.hpp"
#include "memory_budget.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/atomic_file.hpp"
#include "meshstep/io/formats.hpp"
#include "meshstep/refine/registry.hpp"
#include "meshstep/refine/run_spec.hpp"
#include "recipe_file.hpp"
#include "svg_plot.hpp"

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

std::string base_name(const std::string& path) { return std::filesystem::path(path).filename().string(); }

// Shortest text that reads back as the same double (a bound as the command line gives it:
// 30, 22.5, 1e-06).
std::string bound_text(double v) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, v).ptr;
  return std::string(buffer, end);
}

std::string mib(std::size_t bytes) { return fixed(static_cast<double>(bytes) / 1048576.0, 1); }

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

  // Every phase any run has, in the order they first appear.
  std::vector<std::string> phases;
  for (const LoggedRun& r : runs)
    for (const auto& [name, steps] : r.phase_steps)
      if (std::find(phases.begin(), phases.end(), name) == phases.end()) phases.push_back(name);
  const auto steps_in = [](const LoggedRun& r, const std::string& phase) -> std::optional<std::uint64_t> {
    for (const auto& [name, steps] : r.phase_steps)
      if (name == phase) return steps;
    return std::nullopt;
  };

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

  if (args.json) {
    std::string out = "{\"runs\":[";
    for (std::size_t i = 0; i < runs.size(); ++i) {
      const LoggedRun& r = runs[i];
      JsonLine phase_steps;
      for (const auto& [name, steps] : r.phase_steps) phase_steps.field(name, static_cast<std::size_t>(steps));
      JsonLine j;
      j.field("log", r.path)
          .field("caption", r.caption)
          .field("input", r.input)
          .field("input_hash", r.input_hash)
          .field("algorithm", r.algorithm)
          .field("ds", r.data_structure)
          .field("insertion", r.insertion)
          .field("vertices", r.vertices)
          .field("triangles", r.triangles)
          .field("steiner", r.steiner)
          .field("min_angle", r.min_angle)
          .field("max_angle", r.max_angle)
          .field("steps", static_cast<std::size_t>(r.steps))
          .object("phase_steps", phase_steps)
          // A log keeps no clock: its run's time is not known here (refine --stats json has it).
          .field("ms", std::nan(""));
      out += (i ? "," : "") + j.str();
    }
    out += std::string("],\"same_input\":") + (different_inputs_warning(runs).empty() ? "true" : "false") + "}";
    std::printf("%s\n", out.c_str());
    return kExitOk;
  }

  std::vector<std::string> header = {""};
  for (const LoggedRun& r : runs) header.push_back(base_name(r.path));
  TextTable table(header);
  const auto row = [&](const std::string& name, auto cell) {
    std::vector<std::string> cells = {name};
    for (const LoggedRun& r : runs) cells.push_back(cell(r));
    table.add_row(cells);
  };
  row("run", [](const LoggedRun& r) { return r.caption; });
  row("input", [](const LoggedRun& r) { return base_name(r.input); });
  row("Steiner points", [](const LoggedRun& r) { return std::to_string(r.steiner); });
  row("triangles", [](const LoggedRun& r) { return std::to_string(r.triangles); });
  row("smallest angle", [](const LoggedRun& r) { return fixed(r.min_angle, 2); });
  row("largest angle", [](const LoggedRun& r) { return fixed(r.max_angle, 2); });
  row("steps", [](const LoggedRun& r) { return std::to_string(r.steps); });
  for (const std::string& phase : phases)
    row("  " + phase, [&](const LoggedRun& r) {
      const auto steps = steps_in(r, phase);
      return steps ? std::to_string(*steps) : std::string("-");
    });
  row("time", [](const LoggedRun&) { return std::string("not in the log"); });
  std::printf("%s", table.text().c_str());
  return kExitOk;
}

// ---------------------------------------------------------------------------------------
// compare --algorithms A,B,... INPUT...

// The runs of the matrix, or the exit status of the first problem (printed).
struct Matrix {
  std::vector<MatrixRun> runs;
  std::vector<std::string> labels;  // in the command line's order; the first is the reference
  std::vector<double> bounds;       // the sweep's (empty: --min-angle not swept)
};

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

// A run's peak memory as the run's own budget accounts for it (memory_budget.hpp: the
// measured peak resident bytes per triangle of a refinement, rounded up): an estimate, the
// same for every algorithm per triangle, since two runs at once share one process's memory.
std::size_t memory_estimate(const MatrixRow& row) {
  return static_cast<std::size_t>(kBytesPerTriangle) * row.smallest_angles.size();
}

double run_ms(const MatrixRow& row) { return row.result.report.triangulate_ms + row.result.report.refine_ms; }

std::string json_rows(const Matrix& m, const std::vector<MatrixRow>& rows) {
  std::string out = "[";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const MatrixRun& run = m.runs[i];
    const RefineReport& r = rows[i].result.report;
    JsonLine ms;
    ms.field("triangulate", r.triangulate_ms).field("refine", r.refine_ms);
    JsonLine j;
    j.field("algorithm", run.label).field("input", run.input);
    if (!std::isnan(run.sweep_bound)) j.field("min_angle_bound", run.sweep_bound);
    j.field("vertices", rows[i].vertices)
        .field("triangles", rows[i].smallest_angles.size())
        .field("steiner", r.steiner_vertices)
        .field("min_angle", rows[i].result.angles.min_angle_deg)
        .field("max_angle", rows[i].result.angles.max_angle_deg)
        .field("below_min_angle", r.below_min_angle)
        .field("bad_triangles", r.bad_triangles)
        .field("bad_near_small_input_angle", r.bad_near_small_input_angle)
        .field("bounds_met", r.bounds_met)
        .field("stopped_by_cap", r.stopped_by_cap)
        .field("memory_estimate_bytes", memory_estimate(rows[i]))
        .object("ms", ms);
    out += (i ? "," : "") + j.str();
  }
  return out + "]";
}

// Steiner points against the angle bound (summed over the inputs), and the distribution of
// the triangles' smallest angles at the last bound (pooled over the inputs), per algorithm.
std::string plot_svg(const Matrix& m, const std::vector<MatrixRow>& rows, std::size_t inputs) {
  std::vector<PlotPanel> panels;
  const bool swept = m.bounds.size() > 1;
  char letter = 'a';
  // Panels are lettered when there are two.
  const auto title = [&letter, swept](const std::string& words) {
    return swept ? std::string("(") + letter++ + ") " + words : words;
  };
  if (swept) {
    PlotPanel p;
    p.title = title("Steiner points against the angle bound");
    p.x_label = "angle bound (degrees)";
    p.y_label = inputs > 1 ? "Steiner points (sum over " + std::to_string(inputs) + " inputs)" : "Steiner points";
    p.y_from_zero = true;
    if (m.bounds.size() <= 12) p.x_ticks = m.bounds;  // every bound swept, labelled
    for (const std::string& label : m.labels) {
      PlotSeries s{label, {}, true};
      for (const double bound : m.bounds) {
        double total = 0;
        for (std::size_t i = 0; i < rows.size(); ++i)
          if (m.runs[i].label == label && m.runs[i].sweep_bound == bound)
            total += static_cast<double>(rows[i].result.report.steiner_vertices);
        s.points.emplace_back(bound, total);
      }
      p.series.push_back(std::move(s));
    }
    panels.push_back(std::move(p));
  }
  PlotPanel cdf;
  const double last = m.bounds.empty() ? std::nan("") : m.bounds.back();
  cdf.title = title(std::isnan(last) ? "Smallest angle of each triangle"
                                     : "Smallest angle of each triangle, bound " + bound_text(last) + "\u00b0");
  cdf.x_label = "smallest angle of a triangle (degrees)";
  cdf.y_label = "fraction of triangles at or below";
  cdf.y_range = std::pair{0.0, 1.0};
  double low = 60.0;
  for (const std::string& label : m.labels) {
    std::vector<float> angles;
    for (std::size_t i = 0; i < rows.size(); ++i)
      if (m.runs[i].label == label && (std::isnan(last) || m.runs[i].sweep_bound == last))
        angles.insert(angles.end(), rows[i].smallest_angles.begin(), rows[i].smallest_angles.end());
    std::sort(angles.begin(), angles.end());
    PlotSeries s{label, {}, false};
    // The empirical CDF as a staircase, thinned to about 600 corners.
    const std::size_t n = angles.size(), stride = std::max<std::size_t>(n / 600, 1);
    for (std::size_t k = 0; k < n; k += stride) {
      const double fraction_before = static_cast<double>(k) / static_cast<double>(n);
      s.points.emplace_back(angles[k], fraction_before);
      const std::size_t next = std::min(k + stride, n);
      s.points.emplace_back(angles[k], static_cast<double>(next) / static_cast<double>(n));
    }
    if (n) {
      low = std::min(low, static_cast<double>(angles.front()));
      s.points.emplace_back(60.0, 1.0);
    }
    cdf.series.push_back(std::move(s));
  }
  cdf.x_range = std::pair{std::floor(low / 5.0) * 5.0, 60.0};
  panels.push_back(std::move(cdf));
  return svg_figure(panels);
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

  // The summary: each algorithm's Steiner points over the first's, geometric mean.
  std::vector<std::pair<double, std::size_t>> ratios;
  for (const std::string& label : m.labels) {
    std::size_t pairs = 0;
    const double ratio = geometric_mean_steiner_ratio(m.runs, rows, label, m.labels.front(), &pairs);
    ratios.emplace_back(ratio, pairs);
  }
  const std::size_t peak = peak_rss_bytes();

  if (args.json) {
    JsonLine summary;
    for (std::size_t a = 0; a < m.labels.size(); ++a) summary.field(m.labels[a], ratios[a].first);
    std::string out = "{\"rows\":" + json_rows(m, rows) + ",\"reference\":\"" + m.labels.front() +
                      "\",\"steiner_ratio_geomean\":" + summary.str() + ",\"peak_rss_bytes\":" + std::to_string(peak) +
                      "}";
    std::printf("%s\n", out.c_str());
  } else {
    const bool swept = !m.bounds.empty();
    // For people: short words; for programs (CSV): the JSON's keys.
    std::vector<std::string> header = {"algorithm", "input"};
    if (swept) header.push_back(args.csv ? "min_angle_bound" : "bound");
    if (args.csv)
      for (const char* h : {"steiner", "triangles", "min_angle", "max_angle", "bad_triangles",
                            "bad_near_small_input_angle", "ms", "memory_estimate_kib"})
        header.push_back(h);
    else
      for (const char* h : {"Steiner", "triangles", "min angle", "max angle", "left bad", "at small input angles",
                            "ms", "est. KiB"})
        header.push_back(h);
    TextTable table(header);
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const RefineReport& r = rows[i].result.report;
      std::vector<std::string> cells = {m.runs[i].label, args.csv ? m.runs[i].input : base_name(m.runs[i].input)};
      if (swept) cells.push_back(bound_text(m.runs[i].sweep_bound));
      const int digits = args.csv ? 6 : 2;
      cells.push_back(std::to_string(r.steiner_vertices));
      cells.push_back(std::to_string(rows[i].smallest_angles.size()));
      cells.push_back(fixed(rows[i].result.angles.min_angle_deg, digits));
      cells.push_back(fixed(rows[i].result.angles.max_angle_deg, digits));
      cells.push_back(std::to_string(r.bad_triangles));
      cells.push_back(std::to_string(r.bad_near_small_input_angle));
      cells.push_back(fixed(run_ms(rows[i]), args.csv ? 3 : 1));
      cells.push_back(std::to_string((memory_estimate(rows[i]) + 1023) / 1024));
      table.add_row(std::move(cells));
    }
    if (args.csv) {
      std::printf("%s", table.csv().c_str());
    } else {
      std::printf("%s", table.text().c_str());
      std::printf("\nSteiner points relative to %s (geometric mean of the ratios over the runs both finished):\n",
                  m.labels.front().c_str());
      for (std::size_t a = 0; a < m.labels.size(); ++a)
        std::printf("  %-24s %s  (%zu run%s)\n", m.labels[a].c_str(), fixed(ratios[a].first, 3).c_str(),
                    ratios[a].second, ratios[a].second == 1 ? "" : "s");
      std::printf("Peak resident memory of this process (all %zu runs, %u at a time): %s MiB\n", rows.size(),
                  std::max(args.jobs, 1u), mib(peak).c_str());
    }
  }

  if (!args.plot.empty()) {
    try {
      io::write_file_atomically(args.plot, plot_svg(m, rows, args.files.size()));
    } catch (const InputError& e) {
      print_error(e.what());
      return kExitBadInput;
    }
  }
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
  cmd->add_flag("--csv", args->csv, "CSV instead of text (--algorithms: one line per run)");
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
