// Helpers shared by the triangulation tests: run every data structure x insertion
// strategy, check each result independently, and demand identical triangle sets; the
// shared corpus.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "meshstep/check/mesh_check.hpp"
#include "meshstep/check/quality.hpp"
#include "meshstep/delaunay/triangulate.hpp"

namespace meshstep::testing {

// n points uniform in the unit square, reproducible from the seed.
inline std::vector<Point> random_unit_points(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point> p(n);
  for (Point& q : p) q = {u(rng), u(rng)};
  return p;
}

inline std::vector<TriangulateOptions> all_configurations(bool convex_hull = false) {
  std::vector<TriangulateOptions> configs;
  for (const DataStructure ds : {DataStructure::tds, DataStructure::dcel})
    for (const Insertion ins : {Insertion::flip, Insertion::cavity}) {
      TriangulateOptions o;
      o.data_structure = ds;
      o.insertion = ins;
      o.convex_hull = convex_hull;
      o.compute_neighbors = true;
      configs.push_back(o);
    }
  return configs;
}

inline std::string describe(const TriangulateOptions& o) {
  return std::string(to_string(o.data_structure)) + "/" + to_string(o.insertion);
}

// Triangulates `input` with every configuration; each mesh must pass the checker, and all
// must have the same triangles. Returns the first mesh.
inline TriMesh triangulate_everywhere(const Pslg& input, bool convex_hull = false,
                                      TriangulateReport* first_report = nullptr) {
  TriMesh first;
  std::vector<std::array<std::uint32_t, 3>> reference;
  bool have_reference = false;
  for (const TriangulateOptions& o : all_configurations(convex_hull)) {
    TriangulateReport report;
    TriMesh mesh = triangulate(input, o, &report);
    const CheckReport check = check_mesh(mesh, &input);
    EXPECT_TRUE(check.ok) << describe(o) << ": "
                          << (check.problems.empty() ? std::string() : check.problems.front());
    const auto canonical = canonical_triangles(mesh);
    if (!have_reference) {
      reference = canonical;
      first = std::move(mesh);
      if (first_report) *first_report = report;
      have_reference = true;
    } else {
      EXPECT_EQ(canonical, reference) << describe(o) << " differs from " << describe(all_configurations()[0]);
    }
  }
  return first;
}

inline std::filesystem::path shared_data() { return MESHSTEP_SHARED_DATA; }

// The .poly files of the shared corpus, sorted (none when it is absent: the suites that use
// them then have no instances and say so).
inline std::vector<std::string> corpus_polys() {
  std::vector<std::string> files;
  const std::filesystem::path dir = shared_data() / "pslg";
  if (!std::filesystem::is_directory(dir)) return files;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.path().extension() == ".poly") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

// "p2t_tank.poly" -> "p2t_tank_poly": a test name for a corpus file.
inline std::string corpus_test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = std::filesystem::path(info.param).filename().string();
  std::replace_if(name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
  return name;
}

}  // namespace meshstep::testing
