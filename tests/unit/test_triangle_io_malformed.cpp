// Broken Triangle files: each must be refused with an InputError naming the file and the
// 1-based line, and saying what is wrong. Random garbage, truncations and mutations of valid
// files must either read or be refused that way: never crash, hang or throw anything else.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "meshstep/error.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;
using namespace meshstep;

namespace {

using meshstep::testing::TempDir;

// Runs `read`, which must throw an InputError for `path` at `line` whose message contains
// `keyword`.
void expect_error(const std::function<void()>& read, const std::string& path,
                  std::size_t line, const std::string& keyword) {
  try {
    read();
    ADD_FAILURE() << "no error for " << path << " (expected line " << line << ", \""
                  << keyword << "\")";
  } catch (const InputError& e) {
    const std::string what = e.what();
    // InputError writes "FILE: message" when there is no line (the file cannot be opened).
    const std::string prefix = path + (line == 0 ? "" : ":" + std::to_string(line)) + ": ";
    EXPECT_EQ(what.rfind(prefix, 0), 0u) << what << "\n  expected prefix: " << prefix;
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), line) << what;
    EXPECT_NE(what.find(keyword), std::string::npos) << what << "\n  expected: " << keyword;
  }
}

struct BrokenFile {
  const char* name;  // file name: its extension picks the reader
  std::string content;
  std::size_t line;
  const char* keyword;
};

// A file of `n` 1-based vertices on a row, no attributes, no markers.
std::string node_rows(std::size_t n) {
  std::string s = std::to_string(n) + " 2 0 0\n";
  for (std::size_t i = 1; i <= n; ++i) s += std::to_string(i) + " " + std::to_string(i) + " 0\n";
  return s;
}

const std::string kPad = "   # a comment long enough to rule out the size check\n";

std::vector<BrokenFile> broken_pslg_files() {
  return {
      {"empty.node", "", 1, "empty"},
      {"comments.node", "# only\n# comments\n\n", 3, "empty"},
      {"truncated.node", "3 2 0 0\n1 0 0" + kPad + "2 1 1" + kPad, 3,
       "unexpected end of file: found 2 of the 3 vertices declared on line 1"},
      {"nan.node", "2 2 0 0\n1 0 0\n2 nan 1\n", 3, "finite"},
      {"inf.node", "2 2 0 0\n1 0 0\n2 1 -inf\n", 3, "finite"},
      {"infinity.node", "1 2 0 0\n1 infinity 0\n", 2, "finite"},
      {"word.node", "2 2 0 0\n1 0 0\n2 zero 0\n", 3, "should be a number, found 'zero'"},
      {"hex.node", "1 2 0 0\n1 0x10 0\n", 2, "should be a number, found '0x10'"},
      {"fraction_number.node", "2 2 0 0\n1.5 0 0\n2 1 1\n", 2,
       "vertex number should be an integer, found '1.5'"},
      {"fraction_count.node", "2.0 2 0 0\n1 0 0\n2 1 1\n", 1,
       "number of vertices should be an integer, found '2.0'"},
      {"negative_count.node", "-3 2 0 0\n", 1, "negative"},
      {"dimension.node", "1 3 0 0\n1 0 0 0\n", 1, "dimension must be 2, found 3"},
      {"absurd.node", "1000000000000 2 0 0\n1 0 0\n", 1, "declares 1000000000000 vertices"},
      {"too_many_for_size.node", "5000 2 0 0\n1 0 0\n2 1 1\n", 1, "can hold at most"},
      {"huge_integer.node", "99999999999999999999 2 0 0\n", 1,
       "number of vertices '99999999999999999999' is out of range"},
      {"absurd_attributes.node", "1 2 999999999 0\n1 0 0\n", 1, "attributes"},
      {"nul.node", std::string("2 2 0 0\n1 0 0\n2 1\0 1\n", 21), 3, "binary data (byte 0x00"},
      {"control.node", "1 2 0 0\n1 0 0 # bell \x07 in a comment\n", 2, "binary data (byte 0x07"},
      {"non_ascii.node", "1 2 0 0\n1 0 \xC3\xA9\n", 2, "found '\\xC3\\xA9'"},
      {"gap.node", "3 2 0 0\n1 0 0\n2 1 0\n4 0 1\n", 4,
       "vertex numbers must be consecutive: expected 3, found 4"},
      {"first_number.node", "2 2 0 0\n5 0 0\n6 1 1\n", 2, "must start at 0 or 1"},
      {"marker_flag.node", "1 2 0 2\n1 0 0 1 1\n", 1,
       "number of boundary markers must be 0 or 1, found 2"},
      {"too_many_fields.node", "1 2 0 0\n1 0 0 0\n", 2,
       "expected 3 numbers (vertex number, x, y), found 4"},
      {"too_few_attributes.node", "1 2 2 1\n1 0 0 5 1" + kPad, 2,
       "expected 6 numbers (vertex number, x, y, 2 attributes, marker), found 5"},
      {"overflow_double.node", "1 2 0 0\n1 1e400 0\n", 2, "out of the range of a double"},
      {"marker_overflow.node", "1 2 0 1\n1 0 0 3000000000\n", 2, "does not fit in an int"},
      {"header_fields.node", "3 2\n", 1, "expected 4 numbers (number of vertices, dimension"},
      {"binary_no_newline.node", "3 2 0 0\n" + std::string(2u << 20, '\x01'), 2,
       "binary data (byte 0x01 in column 1)"},
      {"long_line.node", "1 2 0 0\n" + std::string(3u << 20, '1') + "\n", 2, "longer than"},
      {"no_segments.poly", node_rows(3), 4, "unexpected end of file: expected the segment"},
      {"no_holes.poly", node_rows(3) + "1 0\n1 1 2\n", 6, "expected the hole header"},
      {"segment_flag.poly", node_rows(3) + "1 3\n1 1 2 0\n0\n", 5,
       "number of segment boundary markers must be 0 or 1, found 3"},
      {"segment_range.poly", node_rows(3) + "2 0\n1 1 2\n2 3 4\n0\n", 7,
       "segment endpoint 4 is out of range (vertices are numbered 1..3)"},
      {"segment_zero.poly", node_rows(3) + "1 0\n1 0 1\n0\n", 6,
       "segment endpoint 0 is out of range (vertices are numbered 1..3)"},
      {"segment_base.poly", node_rows(3) + "1 0\n0 1 2\n0\n", 6,
       "numbering starts at 1 in this set of files"},
      {"segments_truncated.poly", node_rows(3) + "3 1\n1 1 2 0" + kPad + "2 2 3 0" + kPad, 7,
       "found 2 of the 3 segments declared on line 5"},
      {"hole_inf.poly", node_rows(3) + "0 0\n1\n1 inf 0\n", 7, "finite"},
      {"hole_fields.poly", node_rows(3) + "0 0\n1\n1 0.5\n", 7,
       "expected 3 numbers (hole number, x, y), found 2"},
      {"region_fields.poly", node_rows(3) + "0 0\n0\n1\n1 0.5 0.5\n", 8,
       "expected 5 numbers (region number, x, y, attribute, maximum area), found 3"},
      {"region_count.poly", node_rows(3) + "0 0\n0\n-1\n", 7, "negative"},
  };
}

}  // namespace

TEST(TriangleIoMalformed, BrokenPslgFilesNameFileLineAndProblem) {
  TempDir dir;
  const auto cases = broken_pslg_files();
  ASSERT_GE(cases.size(), 20u);
  for (const BrokenFile& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string path = dir.write(c.name, c.content);
    expect_error([&] { io::read_pslg(path); }, path, c.line, c.keyword);
  }
}

TEST(TriangleIoMalformed, ExampleMessagesReadExactly) {
  TempDir dir;
  const std::string node = dir.write("x.node",
                                     "5 2 0 1\n"
                                     "# five vertices\n"
                                     "\n"
                                     "1 0 0 1\n2 1 0 1\n3 1 1 1\n"
                                     "4 0.5 0.5\n"
                                     "5 0 1 1\n");
  try {
    io::read_node(node);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              node + ":7: expected 4 numbers (vertex number, x, y, marker), found 3");
  }

  dir.write("y.node", node_rows(29));
  std::string poly = "0 2 0 0\n10 0\n";
  for (int i = 1; i <= 9; ++i) poly += std::to_string(i) + " " + std::to_string(i) + " " +
                                       std::to_string(i + 1) + "\n";
  poly += "10 1 40\n0\n";
  const std::string poly_path = dir.write("y.poly", poly);
  try {
    io::read_poly(poly_path);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              poly_path + ":12: segment endpoint 40 is out of range (vertices are numbered 1..29)");
  }
}

TEST(TriangleIoMalformed, PolyWhoseNodeFileIsMissing) {
  TempDir dir;
  const std::string poly = dir.write("lonely.poly", "# vertices elsewhere\n0 2 0 0\n0 0\n0\n");
  expect_error([&] { io::read_poly(poly); }, poly, 2, dir.file("lonely.node"));
  // An error inside the .node beside names the .node, not the .poly.
  const std::string node = dir.write("lonely.node", "2 2 0 0\n1 0 0" + kPad);
  expect_error([&] { io::read_poly(poly); }, node, 2, "end of file");
}

TEST(TriangleIoMalformed, BrokenMeshFiles) {
  TempDir dir;
  const std::string nodes = "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n";
  const std::string prefix = dir.file("m");
  struct MeshCase {
    const char* ext;
    std::string content;
    std::size_t line;
    const char* keyword;
  };
  const std::vector<MeshCase> cases = {
      {".ele", "1 4 0\n1 1 2 3 4\n", 1, "nodes per triangle must be 3 or 6, found 4"},
      {".ele", "2 3 0\n1 1 2 3\n2 1 3 9\n", 3,
       "triangle vertex 9 is out of range (vertices are numbered 1..4)"},
      {".ele", "1 3 0\n0 1 2 3\n", 2, "numbering starts at 1"},
      {".ele", "2 3 0\n1 1 2 3\n3 1 3 4\n", 3, "consecutive"},
      {".ele", "2 3 1\n1 1 2 3 0" + kPad + "2 1 3 4\n", 3,
       "expected 5 numbers (triangle number, 3 vertices, attribute), found 4"},
      {".ele", "1 6 0\n1 1 2 3 4 1 7\n", 2, "triangle node 7 is out of range"},
      {".ele", "", 1, "empty"},
      {".ele", "1 3\n", 1, "expected 3 numbers"},
  };
  for (const MeshCase& c : cases) {
    SCOPED_TRACE(c.content);
    dir.write("m.node", nodes);
    const std::string path = dir.write(std::string("m") + c.ext, c.content);
    expect_error([&] { io::read_mesh(prefix); }, path, c.line, c.keyword);
  }

  dir.write("m.ele", "2 3 0\n1 1 2 3\n2 1 3 4\n");
  const std::string area = dir.write("m.area", "3\n1 1\n2 1\n3 1\n");
  expect_error([&] { io::read_mesh(prefix); }, area, 1, "but the .ele file has 2");
  dir.write("m.area", "2\n1 1\n2 nan\n");
  expect_error([&] { io::read_mesh(prefix); }, area, 3, "finite");
  fs::remove(area);

  const std::string poly = dir.write("m.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 1 1\n0 0\n0\n");
  expect_error([&] { io::read_mesh(prefix); }, poly, 1, "lists 3 vertices, but the .node");
  dir.write("m.poly", "0 2 0 1\n1 1\n1 1 5 1\n0\n");
  expect_error([&] { io::read_mesh(prefix); }, poly, 3, "segment endpoint 5 is out of range");
  fs::remove(poly);

  fs::remove(dir.file("m.ele"));
  expect_error([&] { io::read_mesh(prefix); }, dir.file("m.ele"), 0, "cannot open");
}

TEST(TriangleIoMalformed, BrokenEdgeAndNeighFiles) {
  TempDir dir;
  TriMesh m;
  m.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.first_index = 1;
  const std::string neigh = dir.file("m.neigh");
  const auto read_neigh = [&] { io::read_neigh(neigh, m); };
  dir.write("m.neigh", "2 3\n1 -1 2 -1\n2 -1 -1 3\n");
  expect_error(read_neigh, neigh, 3, "neighbour 3 is out of range (triangles are numbered 1..2)");
  dir.write("m.neigh", "2 4\n");
  expect_error(read_neigh, neigh, 1, "neighbours per triangle must be 3, found 4");
  dir.write("m.neigh", "3 3\n");
  expect_error(read_neigh, neigh, 1, "declares 3 triangles, but the mesh has 2");
  dir.write("m.neigh", "2 3\n1 -1 2 -1\n2 -1 -2 1\n");
  expect_error(read_neigh, neigh, 3, "neighbour -2 is out of range");

  const std::string edge = dir.file("m.edge");
  const auto read_edge = [&] { io::read_edge(edge, m); };
  dir.write("m.edge", "1 0\n1 1 5\n");
  expect_error(read_edge, edge, 2, "edge endpoint 5 is out of range (vertices are numbered 1..4)");
  dir.write("m.edge", "1 1\n1 1 2" + kPad);
  expect_error(read_edge, edge, 2, "expected 4 numbers (edge number, endpoint, endpoint, marker)");
}

TEST(TriangleIoMalformed, EndlessZeroBytesAreBinary) {
  // A character device has no size to check against and no newline: the reader must stop
  // after one chunk and say why.
  if (!fs::exists("/dev/zero")) GTEST_SKIP() << "no /dev/zero";
  expect_error([] { io::read_node("/dev/zero"); }, "/dev/zero", 1, "binary data (byte 0x00");
}

TEST(TriangleIoMalformed, DirectoryIsNotAFile) {
  TempDir dir;
  fs::create_directory(dir.file("d.node"));
  expect_error([&] { io::read_node(dir.file("d.node")); }, dir.file("d.node"), 0,
               "Is a directory");
}

namespace {

// Reads `path` with `read`; only InputError is an acceptable failure.
void read_or_input_error(const std::function<void()>& read, const std::string& what) {
  try {
    read();
  } catch (const InputError&) {
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << ": unexpected exception: " << e.what();
  } catch (...) {
    ADD_FAILURE() << what << ": unexpected non-standard exception";
  }
}

const std::string kValidPoly =
    "# a square with a hole and two regions\n"
    "8 2 1 1\n"
    "1 0 0 0.5 1\n2 4 0 0.25 1\n3 4 4 1e-3 1\n4 0 4 -7 1\n"
    "5 1 1 0 0\n6 3 1 0 0\n7 3 3 0 0\n8 1 3 0 0\n"
    "8 1\n1 1 2 1\n2 2 3 1\n3 3 4 1\n4 4 1 1\n5 5 6 2\n6 6 7 2\n7 7 8 2\n8 8 5 2\n"
    "1\n1 2 2\n"
    "2\n1 0.5 0.5 1 0.1\n2 3.5 3.5 2 -1\n";

const std::string kValidNode = "4 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n";
const std::string kValidEle = "2 3 0\n1 1 2 3\n2 1 3 4\n";

}  // namespace

TEST(TriangleIoMalformed, RandomGarbageNeverCrashes) {
  TempDir dir;
  std::mt19937_64 rng(20240601);
  // Half the files are arbitrary bytes, half are drawn from the characters of real files so
  // that the parser gets past the header now and then.
  const std::string alphabet = "0123456789012345678901234567890123456789 \n\n\t.-+e#";
  dir.write("fuzz.node", kValidNode);  // for a .poly that declares 0 vertices
  for (int i = 0; i < 300; ++i) {
    const std::size_t size = rng() % 600;
    std::string bytes(size, '\0');
    for (char& c : bytes) {
      c = i % 2 ? static_cast<char>(rng() & 0xFF) : alphabet[rng() % alphabet.size()];
    }
    const std::string poly = dir.write("fuzz.poly", bytes);
    read_or_input_error([&] { io::read_poly(poly); }, "garbage .poly " + std::to_string(i));
    const std::string node = dir.write("junk.node", bytes);
    read_or_input_error([&] { io::read_node(node); }, "garbage .node " + std::to_string(i));
    dir.write("mesh.node", kValidNode);
    dir.write("mesh.ele", bytes);
    read_or_input_error([&] { io::read_mesh(dir.file("mesh")); },
                        "garbage .ele " + std::to_string(i));
  }
}

TEST(TriangleIoMalformed, TruncationsAndMutationsNeverCrash) {
  TempDir dir;
  std::mt19937_64 rng(77);
  ASSERT_NO_THROW(io::read_poly(dir.write("ok.poly", kValidPoly)));
  dir.write("mesh.node", kValidNode);
  dir.write("mesh.ele", kValidEle);
  ASSERT_NO_THROW(io::read_mesh(dir.file("mesh")));

  const std::string alphabet = "0123456789 \n.-e#\x01";
  for (int i = 0; i < 300; ++i) {
    // Truncated at a random byte.
    const std::string cut = kValidPoly.substr(0, rng() % kValidPoly.size());
    const std::string poly = dir.write("cut.poly", cut);
    read_or_input_error([&] { io::read_poly(poly); }, "truncated .poly " + std::to_string(i));

    // A few bytes replaced, inserted or deleted.
    std::string mutated = kValidPoly;
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int k = 0; k < edits && !mutated.empty(); ++k) {
      const std::size_t at = rng() % mutated.size();
      const char c = alphabet[rng() % alphabet.size()];
      switch (rng() % 3) {
        case 0: mutated[at] = c; break;
        case 1: mutated.insert(mutated.begin() + static_cast<std::ptrdiff_t>(at), c); break;
        default: mutated.erase(at, 1); break;
      }
    }
    const std::string mpoly = dir.write("mut.poly", mutated);
    read_or_input_error([&] { io::read_poly(mpoly); }, "mutated .poly " + std::to_string(i));

    dir.write("mesh.ele", kValidEle.substr(0, rng() % kValidEle.size()));
    read_or_input_error([&] { io::read_mesh(dir.file("mesh")); },
                        "truncated .ele " + std::to_string(i));
  }
}
