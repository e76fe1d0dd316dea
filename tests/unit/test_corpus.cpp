// Every PSLG and point set of the shared corpus, on every data structure and insertion
// strategy: valid, covering its input, and identical across configurations.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "meshstep/io/triangle_io.hpp"
#include "triangulate_support.hpp"

namespace meshstep {
namespace {

std::vector<std::string> corpus_files() {
  std::vector<std::string> files;
  const auto dir = testing::shared_data() / "pslg";
  if (!std::filesystem::is_directory(dir)) return files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const auto ext = entry.path().extension();
    if (ext == ".poly" || ext == ".node") files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

class Corpus : public ::testing::TestWithParam<std::string> {};

TEST_P(Corpus, TriangulatesValidlyEverywhere) {
  const Pslg input = io::read_pslg(GetParam());
  testing::triangulate_everywhere(input);  // may be empty (box.poly: one segment)
  const TriMesh hull = testing::triangulate_everywhere(input, /*convex_hull=*/true);
  EXPECT_GT(hull.triangles.size(), 0u);
}

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = std::filesystem::path(info.param).filename().string();
  std::replace_if(name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
  return name;
}

INSTANTIATE_TEST_SUITE_P(SharedData, Corpus, ::testing::ValuesIn(corpus_files()), test_name);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(Corpus);

TEST(CorpusPresence, SharedDataIsThereOrSkipped) {
  if (corpus_files().empty())
    GTEST_SKIP() << "no shared corpus at " << testing::shared_data() << ": corpus tests skipped";
  EXPECT_GE(corpus_files().size(), 30u);
}

}  // namespace
}  // namespace meshstep
