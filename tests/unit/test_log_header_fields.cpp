// The log header's fields that describe the input (replay/log_writer.hpp): every value
// comes back bit for bit through a written log; a malformed line is refused naming the
// field and the line; markers and attribute lines beyond the input's vertices are refused,
// so that a hand-made header cannot make the reader allocate without bound.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/error.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/log_writer.hpp"
#include "temp_dir.hpp"

namespace meshstep::replay {
namespace {

std::string refusal(auto&& parse) {
  try {
    parse();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(LogHeaderFields, ComeBackBitForBitThroughALog) {
  testing::TempDir dir("meshstep_header_fields_");
  const std::string path = dir.file("run.mslog");
  Pslg in;
  in.points = {{0, 0}, {1, 0}, {0, 1}, {0.1, 0.1}};
  in.has_vertex_markers = true;
  in.vertex_markers = {7, 7, -3, 0};
  in.attributes_per_vertex = 2;
  in.vertex_attributes = {0.1, 1e-300, -2.5, 3, std::nextafter(1.0, 2.0), 4, 5, 6};
  in.holes = {{0.3, 1.0 / 3.0}};
  in.regions = {{{0.2, 0.2}, 1.5, 0.01}};
  in.has_segment_markers = true;
  in.segments = {{0, 1, 5}, {1, 2, 5}, {3, 0, 0}};
  LogHeader header;
  header.parameters = "input_vertices=4";
  describe_input(header, in);
  LogWriter writer(path, header);
  TriangulateOptions options;
  options.record = &writer;
  triangulate(in, options);
  writer.finish();

  const LogReader log(path);
  const LogHeader& read = log.header();
  EXPECT_EQ(read.vertex_markers, in.vertex_markers);
  EXPECT_EQ(read.attributes_per_vertex, 2u);
  EXPECT_EQ(read.vertex_attributes, in.vertex_attributes);  // exact: shortest round-trip text
  ASSERT_EQ(read.holes.size(), 1u);
  EXPECT_EQ(read.holes[0].y, 1.0 / 3.0);
  ASSERT_EQ(read.regions.size(), 1u);
  EXPECT_EQ(read.regions[0].max_area, 0.01);
  EXPECT_TRUE(read.has_segment_markers);
  ASSERT_EQ(read.segments.size(), in.segments.size());
  for (std::size_t i = 0; i < in.segments.size(); ++i) {
    EXPECT_EQ(read.segments[i].a, in.segments[i].a) << "segment " << i;
    EXPECT_EQ(read.segments[i].b, in.segments[i].b) << "segment " << i;
  }
}

// An older log has no segments field: it reads, with no segments.
TEST(LogHeaderFields, ALogWithoutSegmentsReadsWithNone) {
  testing::TempDir dir("meshstep_header_fields_");
  const std::string path = dir.file("old.mslog");
  LogHeader header;
  header.parameters = "input_vertices=3";
  LogWriter writer(path, header);
  TriangulateOptions options;
  options.record = &writer;
  Pslg in;
  in.points = {{0, 0}, {1, 0}, {0, 1}};
  triangulate(in, options);
  writer.finish();
  EXPECT_TRUE(LogReader(path).header().segments.empty());
}

TEST(LogHeaderFields, MarkersAreStoredAsRuns) {
  const std::vector<int> markers = {0, 0, 0, 1, 1, 0, -5};
  const std::string text = vertex_markers_field(markers);
  EXPECT_EQ(text, "0 3\n1 2\n0 1\n-5 1\n");
  EXPECT_EQ(parse_vertex_markers_field(text, 7), markers);
  // A million vertices on the boundary take one line.
  EXPECT_EQ(vertex_markers_field(std::vector<int>(1000000, 1)), "1 1000000\n");
}

TEST(LogHeaderFields, MalformedLinesAreRefusedByLine) {
  EXPECT_EQ(refusal([] { parse_holes_field("0 0\n1 x\n"); }), "hole 2: not a number");
  EXPECT_EQ(refusal([] { parse_holes_field("0 0 0\n"); }), "hole 1: more than 2 numbers");
  EXPECT_EQ(refusal([] { parse_holes_field("0 nan\n"); }), "hole 1: a number that is not finite");
  EXPECT_EQ(refusal([] { parse_regions_field("1 2 3\n"); }), "region 1: expected 4 numbers");
  EXPECT_EQ(refusal([] { parse_vertex_attributes_field("0\n", 10); }),
            "vertex attributes line 1: a count of attributes of 1 to 1000 expected");
  EXPECT_EQ(refusal([] { parse_vertex_attributes_field("2\n1 2\n3\n", 10); }), "vertex attributes line 3: expected 2 numbers");
  EXPECT_EQ(refusal([] { parse_vertex_markers_field("1 99999999999\n", 10); }).substr(0, 22), "vertex marker run 1: a");
  EXPECT_EQ(refusal([] { parse_vertex_markers_field("3000000000 1\n", 10); }), "vertex marker run 1: a marker out of range");
}

TEST(LogHeaderFields, NothingBeyondTheInputsVertices) {
  EXPECT_NE(refusal([] { parse_vertex_markers_field("0 6\n1 5\n", 10); }).find("a run of 5 markers where the input has 10 vertices"),
            std::string::npos);
  EXPECT_NE(refusal([] { parse_vertex_attributes_field("1\n1\n2\n3\n", 2); }).find("more vertices than the input's 2"),
            std::string::npos);
  EXPECT_EQ(parse_vertex_markers_field("0 4\n1 6\n", 10).size(), 10u);
  EXPECT_EQ(refusal([] { parse_segments_field("0 1\n1 3\n", 3); }),
            "segment 2: a vertex index beyond the input's 3 vertices");
  EXPECT_EQ(refusal([] { parse_segments_field("0 1 2\n", 3); }), "segment 1: more than 2 numbers");
  EXPECT_EQ(refusal([] { parse_segments_field("0 -1\n", 3); }), "segment 1: not a number");
  EXPECT_EQ(parse_segments_field("0 1\n1 2\n", 3).size(), 2u);
}

// In a log: the field's name and line, as an InputError naming the file.
TEST(LogHeaderFields, ALogWithAMalformedFieldIsRefusedNamingIt) {
  testing::TempDir dir("meshstep_header_fields_");
  const std::string path = dir.file("bad.mslog");
  LogHeader header;
  header.parameters = "input_vertices=3";
  header.vertex_markers = {1, 1, 1, 1, 1};  // more markers than the input has vertices
  LogWriter writer(path, header);
  TriangulateOptions options;
  options.record = &writer;
  Pslg in;
  in.points = {{0, 0}, {1, 0}, {0, 1}};
  triangulate(in, options);
  writer.finish();
  try {
    const LogReader log(path);
    FAIL() << "five markers for three vertices were read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the header's vertex_markers field is malformed: vertex marker run 1"),
              std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace meshstep::replay
