// Issue 31: a damaged input file is refused in words, never reported as "internal error".
// Every reader's damaged-input corpus (the fuzzers' seeds and past findings) goes through
// the real commands, and systematic damage (every byte flipped, every length cut) of a few
// recorded logs, a terrain's and a surface refinement's among them, goes through the core
// entry points those commands use. The rule, as app/cli/main.cpp applies it: a file can make
// meshstep answer or refuse (exit 0 or 1, an InputError), never throw anything else.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "log_bytes.hpp"
#include "meshstep/check/mesh_check.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/surface_io.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/refine/refine.hpp"
#include "meshstep/replay/describe.hpp"
#include "meshstep/replay/invariants.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/replay/verify.hpp"
#include "meshstep/scene/build.hpp"
#include "meshstep/scene/explain.hpp"
#include "meshstep/surface/surface_refine.hpp"
#include "meshstep/terrain/height_grid.hpp"
#include "meshstep/terrain/tin.hpp"
#include "run_cli.hpp"
#include "seeds.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;
using meshstep::testing::CommandResult;
using meshstep::testing::run_meshstep;
using meshstep::testing::slurp;
using meshstep::testing::TempDir;

namespace meshstep {
namespace {

const fs::path kRegressions = MESHSTEP_FUZZ_REGRESSIONS;

std::vector<fs::path> files_in(const fs::path& dir) {
  std::vector<fs::path> files;
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir))
      if (e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

// Runs one command on a damaged file: it may succeed or refuse, in words.
void expect_answer_or_refusal(const std::string& args, const fs::path& dir) {
  const CommandResult r = run_meshstep(args, dir);
  EXPECT_TRUE(r.status == 0 || r.status == 1) << "meshstep " << args << " exited " << r.status << ": " << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << "meshstep " << args << ": " << r.err;
}

// The log commands a user points at a log (log info/dump/mesh/check/verify, render, and
// with `pictures` export, whose PNG frames take a second a log).
void run_log_commands(const fs::path& log, const fs::path& dir, bool pictures = false) {
  const std::string l = "'" + log.string() + "'";
  const std::string out = (dir / "out").string();
  for (const std::string& command :
       {"log info " + l, "log info --json " + l, "log dump " + l, "log dump --jsonl " + l,
        "log mesh --step -1 -o " + out + " " + l, "log mesh --step 1 -o " + out + " " + l,
        "log check " + l, "log verify -q " + l, "render " + l + " -o " + out + ".svg"})
    expect_answer_or_refusal(command, dir);
  if (pictures) {
    fs::remove_all(dir / "frames");
    expect_answer_or_refusal("export " + l + " --frames " + (dir / "frames").string() + " -q", dir);
  }
}

// The core entry points of the log commands, in process: LogReader (info), every event
// (dump), a replay to the end, back and by steps with the mesh written out (mesh), the
// invariant check (check), the verifier (verify, which reports rather than throws), and
// the scene and the step explanation the viewer and render build. Returns what went wrong,
// "" when the file was read or refused with an InputError.
std::string use_log(const std::string& path) {
  try {
    const replay::LogReader log(path);
    for (std::uint64_t e = 0; e < log.event_count(); ++e) {
      const replay::Event event = log.event(e);
      (void)replay::describe(event);
      (void)replay::to_json(event, e, log.step_of_event(e), log.step_of_event(e) < log.step_count());
    }
    replay::Replay cursor(log);
    cursor.seek_event(log.event_count());
    (void)cursor.output_mesh();
    (void)scene::build_scene(cursor, scene::SceneOptions{});
    cursor.seek_step(log.step_count() / 2);
    (void)scene::explain_step(cursor);
    (void)cursor.mesh();
    while (cursor.prev_step()) {
    }
    (void)replay::check_invariants(log, replay::InvariantCheckOptions{});
    try {
      (void)replay::verify(log);
    } catch (const std::exception& e) {
      return std::string("verify threw: ") + e.what();
    }
  } catch (const InputError&) {
  } catch (const std::exception& e) {
    return std::string("not an InputError: ") + e.what();
  }
  return "";
}

std::vector<std::uint8_t> bytes_of(const fs::path& p) {
  const std::string s = slurp(p);
  return {s.begin(), s.end()};
}

void write_bytes(const fs::path& p, const std::vector<std::uint8_t>& bytes) {
  std::ofstream(p, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(bytes.data()),
                                                              static_cast<std::streamsize>(bytes.size()));
}

class DamagedInputs : public ::testing::Test {
 protected:
  // Three real logs as the commands record them: a refinement of a .poly, a terrain and a
  // surface refinement.
  std::vector<fs::path> recorded_logs() {
    std::vector<fs::path> logs;
    const fs::path poly = dir_.write("square_hole.poly", fuzz::seeds::kSmallPolys[0].second);
    const fs::path grid = dir_.write("hill.asc", fuzz::seeds::kHillGrid);
    const fs::path surface = dir_.write("tetra.obj", fuzz::seeds::kTetraObj);
    const std::string out = dir_.file("out");
    for (const auto& [name, args] :
         {std::pair{"refine.mslog", "refine " + poly.string() + " --min-angle 25 -o " + out + " -q --record "},
          std::pair{"terrain.mslog", "terrain " + grid.string() + " --max-error 0.5 -o " + out + ".obj -q --record "},
          std::pair{"surface.mslog", "refine " + surface.string() + " -a lepp-bisection --size 0.5 -o " + out + ".obj -q --record "}}) {
      const fs::path log = dir_.path() / name;
      const CommandResult r = run_meshstep(args + log.string(), dir_.path());
      EXPECT_EQ(r.status, 0) << args << ": " << r.err;
      logs.push_back(log);
    }
    return logs;
  }

  TempDir dir_;
};

TEST_F(DamagedInputs, SeedsAndPastFindingsThroughTheCommands) {
  const fs::path seeds = dir_.path() / "seeds";
  fuzz::seeds::write_seeds(fs::path(MESHSTEP_ASSETS) / "examples", seeds);
  const fs::path scratch = dir_.path() / "scratch";
  fs::create_directories(scratch);

  std::vector<fs::path> logs = files_in(seeds / "replay_log");
  for (const fs::path& f : files_in(kRegressions / "replay_log")) logs.push_back(f);
  ASSERT_GE(logs.size(), 20u);
  for (const fs::path& log : logs) {
    SCOPED_TRACE(log.string());
    run_log_commands(log, scratch, /*pictures=*/true);
  }

  // The surface harness's and the Triangle reader harness's inputs: the first byte picks the reader.
  const char* surface_extensions[] = {".off", ".obj", ".ply", ".stl"};
  for (const std::string harness : {"surface"}) {
    std::vector<fs::path> inputs = files_in(seeds / harness);
    for (const fs::path& f : files_in(kRegressions / harness)) inputs.push_back(f);
    for (const fs::path& f : inputs) {
      const std::vector<std::uint8_t> b = bytes_of(f);
      if (b.empty()) continue;
      const fs::path surface = scratch / ("surface" + std::string(surface_extensions[b[0] % 4]));
      write_bytes(surface, {b.begin() + 1, b.end()});
      expect_answer_or_refusal("refine " + surface.string() + " -a lepp-bisection --size 0.5 -o " + (scratch / "s.obj").string() + " -q", scratch);
      expect_answer_or_refusal("render " + surface.string() + " -o " + (scratch / "s.svg").string() + " -q", scratch);
    }
  }
  for (const fs::path& f : files_in(seeds / "triangle_io")) {
    const std::vector<std::uint8_t> b = bytes_of(f);
    const std::string text(b.begin() + 1, b.end());
    const fs::path prefix = scratch / "mesh";
    if (b[0] % 3 == 2) {  // a mesh: .node and .ele, split at the first NUL
      const auto nul = text.find('\0');
      write_bytes(prefix.string() + ".node", {text.begin(), text.begin() + static_cast<std::ptrdiff_t>(std::min(nul, text.size()))});
      write_bytes(prefix.string() + ".ele", {text.begin() + static_cast<std::ptrdiff_t>(std::min(nul + 1, text.size())), text.end()});
      std::ofstream(prefix.string() + ".area") << "1\n1 0.5\n";
      expect_answer_or_refusal("check " + prefix.string() + " -q", scratch);
      expect_answer_or_refusal("refine " + prefix.string() + " --min-angle 20 -o " + (scratch / "r").string() + " -q", scratch);
      expect_answer_or_refusal("render " + prefix.string() + " -o " + (scratch / "m.svg").string() + " -q", scratch);
    } else {
      const fs::path input = scratch / (b[0] % 3 == 0 ? "input.node" : "input.poly");
      write_bytes(input, {text.begin(), text.end()});
      expect_answer_or_refusal("refine " + input.string() + " --min-angle 20 --max-steiner 200 -o " + (scratch / "r").string() + " -q", scratch);
      expect_answer_or_refusal("render " + input.string() + " -o " + (scratch / "i.svg").string() + " -q", scratch);
    }
  }
  for (const std::string harness : {"esri_grid", "terrain"})
    for (const fs::path& f : files_in(seeds / harness))
      expect_answer_or_refusal("terrain " + f.string() + " --max-error 0.5 -o " + (scratch / "t.obj").string() + " -q", scratch);
}

// Every byte of three real logs flipped (as they are, with their checksums remade so that
// the damage reaches the events and keyframes, and with their payloads stored raw), and
// every length of them cut short.
TEST_F(DamagedInputs, EveryByteFlippedAndEveryLengthCutThroughTheLogEntryPoints) {
  const fs::path damaged = dir_.path() / "damaged.mslog";
  std::size_t variants = 0;
  // The first case of each kind of problem (its message without the numbers), and a count.
  std::map<std::string, std::pair<std::string, std::size_t>> problems;
  const auto try_bytes = [&](const std::vector<std::uint8_t>& bytes, const std::string& what) {
    write_bytes(damaged, bytes);
    ++variants;
    const std::string problem = use_log(damaged.string());
    if (problem.empty()) return;
    std::string kind;
    for (const char c : problem)
      if (!std::isdigit(static_cast<unsigned char>(c))) kind += c;
    auto& [first, count] = problems[kind];
    if (count++ == 0) first = what + ": " + problem;  // (the temporary folder's digits go too)
  };
  for (const fs::path& log : recorded_logs()) {
    const std::vector<std::uint8_t> original = bytes_of(log);
    const std::vector<std::uint8_t> raw = fuzz::with_raw_payloads(original);
    ASSERT_GT(original.size(), 100u) << log;
    for (std::size_t cut = 0; cut < original.size(); ++cut)
      try_bytes({original.begin(), original.begin() + static_cast<std::ptrdiff_t>(cut)},
                log.filename().string() + " cut to " + std::to_string(cut) + " bytes");
    for (const auto& [form, base] : {std::pair{"compressed", &original}, std::pair{"raw", &raw}})
      for (std::size_t i = 0; i < base->size(); ++i)
        for (const bool remake_checksums : {false, true}) {
          if (!remake_checksums && std::string(form) == "raw") continue;
          std::vector<std::uint8_t> bytes = *base;
          bytes[i] ^= 0x5A;
          if (remake_checksums) fuzz::fix_checksums(bytes);
          try_bytes(bytes, log.filename().string() + " (" + form + ") byte " + std::to_string(i) + " flipped" +
                               (remake_checksums ? ", checksums remade" : ""));
        }
  }
  EXPECT_GT(variants, 3000u);
  for (const auto& [kind, first] : problems)
    ADD_FAILURE() << first.second << " variants like " << first.first;
}

// Runs f on a damaged text input; returns what went wrong, "" for an answer or an InputError.
template <class F>
std::string answer_or_refusal(F&& f) {
  try {
    f();
  } catch (const InputError&) {
  } catch (const std::exception& e) {
    return std::string("not an InputError: ") + e.what();
  }
  return "";
}

// What `refine`/`triangulate`, `check`, `refine PREFIX`, `terrain` and `refine SURFACE` do
// with a file of each kind, in process, small caps keeping every run short.
void use_pslg(const std::string& path) {
  RefineOptions options;
  options.criteria.min_angle_deg = 20;
  options.criteria.max_steiner = 50;
  (void)refine(io::read_pslg(path), options);
}
void use_mesh(const std::string& prefix) {
  const TriMesh mesh = io::read_mesh(prefix);
  (void)check_mesh(mesh);
  RefineOptions options;
  options.criteria.min_angle_deg = 20;
  options.criteria.max_steiner = 50;
  (void)refine_mesh(mesh, options);
}
void use_grid(const std::string& path) {
  const terrain::HeightGrid grid = terrain::read_height_grid(path);
  if (grid.nx * grid.ny > 4096) return;  // the algorithm's cost, not its correctness
  const auto [low, high] = grid.height_range();
  terrain::TerrainOptions options;
  options.max_error = 0.05 * (static_cast<double>(high) - low);
  options.max_triangles = 200;
  options.improve = true;
  (void)terrain::approximate(grid, options);
}
void use_surface(const std::string& path) {
  surface::BisectionOptions options;
  options.max_edge = 0.5;
  options.max_triangles = 200;
  (void)surface::bisect_surface(io::read_surface(path), options);
}

// Every length of each small text input cut, and each of its bytes replaced by a few texts
// a damaged file holds (a sign, a digit, a separator, an exponent, a huge number, nothing),
// through its reader and the command that consumes it.
TEST_F(DamagedInputs, EveryTextInputCutAndEditedThroughTheReadersAndTheirCommands) {
  const fs::path seeds = dir_.path() / "seeds";
  fuzz::seeds::write_seeds(fs::path(MESHSTEP_ASSETS) / "examples", seeds);
  struct Input {
    std::string text, file;  // its bytes, and the name it is read under
    void (*use)(const std::string&);
    std::string path;  // what `use` is given (a mesh: its prefix)
  };
  std::vector<Input> inputs;
  const fs::path work = dir_.path() / "work";
  fs::create_directories(work);
  const std::string prefix = (work / "mesh").string();
  for (const fs::path& f : files_in(seeds / "triangle_io")) {
    const std::string b = slurp(f);
    const std::string text = b.substr(1);
    if (b[0] % 3 == 2) {  // a mesh: damage its .node, its .ele, and an .area beside them
      const std::size_t nul = text.find('\0');
      const std::string node = text.substr(0, nul), ele = text.substr(nul + 1);
      dir_.write("work/mesh.node", node);
      dir_.write("work/mesh.ele", ele);
      inputs.push_back({node, prefix + ".node", use_mesh, prefix});
      inputs.push_back({ele, prefix + ".ele", use_mesh, prefix});
      inputs.push_back({"3 1\n1 0.5\n2 -1\n3 2e-3\n", prefix + ".area", use_mesh, prefix});
    } else {
      const std::string file = (work / (b[0] % 3 == 0 ? "input.node" : "input.poly")).string();
      inputs.push_back({text, file, use_pslg, file});
    }
  }
  for (const std::string harness : {"esri_grid", "terrain"})
    for (const fs::path& f : files_in(seeds / harness))
      inputs.push_back({slurp(f), (work / "grid.asc").string(), use_grid, (work / "grid.asc").string()});
  const char* surface_extensions[] = {".off", ".obj", ".ply", ".stl"};
  for (const fs::path& f : files_in(seeds / "surface")) {
    const std::string b = slurp(f);
    const std::string file = (work / ("surface" + std::string(surface_extensions[b[0] % 4]))).string();
    inputs.push_back({b.substr(1), file, use_surface, file});
  }
  ASSERT_GE(inputs.size(), 15u);

  std::map<std::string, std::pair<std::string, std::size_t>> problems;  // by kind, as above
  std::size_t variants = 0;
  for (const Input& in : inputs) {
    const auto try_text = [&](const std::string& text, const std::string& what) {
      dir_.write(fs::relative(in.file, dir_.path()).string(), text);
      ++variants;
      const std::string problem = answer_or_refusal([&] { in.use(in.path); });
      if (problem.empty()) return;
      std::string kind;
      for (const char c : problem)
        if (!std::isdigit(static_cast<unsigned char>(c))) kind += c;
      auto& [first, count] = problems[kind];
      if (count++ == 0) first = fs::path(in.file).filename().string() + " " + what + ": " + problem + "\n" + text;
    };
    for (std::size_t cut = 0; cut < in.text.size(); ++cut)
      try_text(in.text.substr(0, cut), "cut to " + std::to_string(cut) + " bytes");
    for (std::size_t i = 0; i < in.text.size(); ++i)
      for (const char* edit : {"-", "9", " ", "\n", "e", "9e307", "0", ""}) {
        try_text(in.text.substr(0, i) + edit + in.text.substr(i + 1),
                 "byte " + std::to_string(i) + " replaced by '" + edit + "'");
      }
    dir_.write(fs::relative(in.file, dir_.path()).string(), in.text);  // whole again for the next
  }
  EXPECT_GT(variants, 10000u);
  for (const auto& [kind, first] : problems)
    ADD_FAILURE() << first.second << " variants like " << first.first;
}

// The two cases (tests/fuzz/regressions/replay_log/): a face write that contradicts
// the mesh it applies to, and a damaged keyframe slot header. `log verify` refuses both in
// its words for damage, with exit 1; verify() reports them and throws nothing.
TEST_F(DamagedInputs, VerifyRefusesAnInconsistentLogAndADamagedKeyframeInItsWords) {
  for (const auto& [name, says] :
       {std::pair{"face_write_contradicting_the_mesh", "expects face slot 0 to hold (0 3 2) but it holds (3 3 2) (the log is inconsistent)"},
        std::pair{"damaged_keyframe_slot_header", "bad keyframe slot header (the file is corrupted)"}}) {
    const std::string log = (kRegressions / "replay_log" / name).string();
    const CommandResult r = run_meshstep("log verify " + log, dir_.path());
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.rfind("meshstep: error: " + log + ": ", 0), 0u) << r.err;  // the path once
    EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
    const replay::LogReader reader(log);
    replay::VerifyReport report;
    EXPECT_NO_THROW(report = replay::verify(reader));
    EXPECT_FALSE(report.ok);
    EXPECT_NE(report.problem.find(says), std::string::npos) << report.problem;
  }
}

// The same damage, a sample of it, through the commands themselves.
TEST_F(DamagedInputs, FlippedBytesThroughTheLogCommands) {
  const fs::path scratch = dir_.path() / "scratch";
  fs::create_directories(scratch);
  const fs::path damaged = dir_.path() / "damaged.mslog";
  for (const fs::path& log : recorded_logs()) {
    std::vector<std::uint8_t> raw = fuzz::with_raw_payloads(bytes_of(log));
    for (std::size_t i = 0; i < raw.size(); i += 97) {
      std::vector<std::uint8_t> bytes = raw;
      bytes[i] ^= 0x5A;
      fuzz::fix_checksums(bytes);
      write_bytes(damaged, bytes);
      SCOPED_TRACE(log.filename().string() + " byte " + std::to_string(i));
      run_log_commands(damaged, scratch);
    }
  }
}

}  // namespace
}  // namespace meshstep
