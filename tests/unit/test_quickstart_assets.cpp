// The example inputs of assets/examples/ (used by `.ci/quickstart demo` and the README):
// they read, triangulate to the triangle counts their comments promise, pass the checker
// with every data structure and insertion strategy, and go through the command line the
// way the README shows.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "meshstep/check/mesh_check.hpp"
#include "meshstep/check/quality.hpp"
#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/io/triangle_io.hpp"

namespace {

namespace fs = std::filesystem;

std::string asset(const std::string& name) {
  return std::string(MESHSTEP_ASSETS) + "/examples/" + name;
}

std::vector<meshstep::TriangulateOptions> all_configurations() {
  std::vector<meshstep::TriangulateOptions> list;
  for (auto ds : {meshstep::DataStructure::tds, meshstep::DataStructure::dcel}) {
    for (auto insertion : {meshstep::Insertion::flip, meshstep::Insertion::cavity}) {
      meshstep::TriangulateOptions options;
      options.data_structure = ds;
      options.insertion = insertion;
      list.push_back(options);
    }
  }
  return list;
}

std::string describe(const meshstep::TriangulateOptions& options) {
  return std::string(meshstep::to_string(options.data_structure)) + "/" +
         meshstep::to_string(options.insertion);
}

std::string join(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& line : lines) out += line + "\n";
  return out;
}

// Triangulates `input` with every configuration; checks each mesh, its triangle count and
// that all configurations give the same triangles.
void expect_every_configuration(const meshstep::Pslg& input, std::size_t triangles,
                                std::size_t steiner) {
  std::vector<std::array<std::uint32_t, 3>> first;
  for (const auto& options : all_configurations()) {
    SCOPED_TRACE(describe(options));
    meshstep::TriangulateReport report;
    const meshstep::TriMesh mesh = meshstep::triangulate(input, options, &report);
    EXPECT_EQ(mesh.triangles.size(), triangles);
    EXPECT_EQ(report.steiner_vertices, steiner);
    EXPECT_EQ(report.duplicate_vertices, 0u);
    const meshstep::CheckReport check = meshstep::check_mesh(mesh, &input);
    EXPECT_TRUE(check.ok) << join(check.problems);
    const auto canonical = meshstep::canonical_triangles(mesh);
    if (first.empty()) {
      first = canonical;
    } else {
      EXPECT_EQ(canonical, first) << "not the same triangles as tds/flip";
    }
  }
}

TEST(QuickstartAssets, PlateHasTwoHolesAndCrossingCracks) {
  std::vector<std::string> warnings;
  const meshstep::Pslg input = meshstep::io::read_pslg(asset("plate.poly"), &warnings);
  EXPECT_TRUE(warnings.empty()) << join(warnings);
  EXPECT_EQ(input.points.size(), 45u);
  EXPECT_EQ(input.segments.size(), 41u);
  EXPECT_EQ(input.holes.size(), 2u);
  EXPECT_EQ(input.first_index, 1);
  // 46 vertices (45 + the crossing of the cracks), 39 of them on the outer boundary and the
  // two hole boundaries, 7 inside, 2 holes: 2*7 + 39 + 2*2 - 2 = 55 triangles.
  expect_every_configuration(input, 55, 1);
}

TEST(QuickstartAssets, CocircularPointsGiveOneMesh) {
  std::vector<std::string> warnings;
  const meshstep::Pslg input = meshstep::io::read_pslg(asset("cocircular.node"), &warnings);
  EXPECT_TRUE(warnings.empty()) << join(warnings);
  ASSERT_EQ(input.points.size(), 37u);
  EXPECT_TRUE(input.segments.empty());
  // 37 points, 12 on the convex hull: 2*37 - 12 - 2 = 60 triangles.
  expect_every_configuration(input, 60, 0);
}

// A scratch folder for one test, removed afterwards.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name)
      : path_(fs::temp_directory_path() /
              ("meshstep_" + name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// Runs the meshstep program with `args`, stdout and stderr into `log`; its exit status.
int run_meshstep(const std::string& args, const fs::path& log) {
  const std::string command =
      quote(MESHSTEP_BINARY) + " " + args + " >" + quote(log.string()) + " 2>&1";
  const int status = std::system(command.c_str());
  if (status == -1 || !WIFEXITED(status)) return -1;
  return WEXITSTATUS(status);
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// What `.ci/quickstart demo` does: triangulate the plate with statistics, then check it.
TEST(QuickstartAssets, DemoCommandsSucceed) {
  ScratchDir dir("quickstart_demo");
  const std::string prefix = (dir.path() / "plate").string();
  const fs::path log = dir.path() / "log.txt";

  ASSERT_EQ(run_meshstep("triangulate " + quote(asset("plate.poly")) + " -o " + quote(prefix) +
                             " --stats json",
                         log),
            0)
      << slurp(log);
  EXPECT_TRUE(fs::exists(prefix + ".node"));
  EXPECT_TRUE(fs::exists(prefix + ".ele"));
  EXPECT_TRUE(fs::exists(prefix + ".poly"));
  const std::string stats = slurp(log);
  EXPECT_NE(stats.find('{'), std::string::npos) << "no JSON statistics printed:\n" << stats;

  EXPECT_EQ(run_meshstep("check " + quote(prefix) + " --poly " + quote(asset("plate.poly")), log),
            0)
      << slurp(log);

  const meshstep::TriMesh mesh = meshstep::io::read_mesh(prefix);
  EXPECT_EQ(mesh.triangles.size(), 55u);
}

// The README's other example: the point set, with the DCEL and cavity insertion, no files.
TEST(QuickstartAssets, ReadmeOptionsWork) {
  ScratchDir dir("quickstart_readme");
  const fs::path log = dir.path() / "log.txt";
  EXPECT_EQ(run_meshstep("triangulate " + quote(asset("cocircular.node")) +
                             " --ds dcel --insertion cavity --no-output -q",
                         log),
            0)
      << slurp(log);
  EXPECT_EQ(run_meshstep("triangulate", log), 2) << slurp(log);
}

}  // namespace
