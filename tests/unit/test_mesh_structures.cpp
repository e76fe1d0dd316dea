// The two TriangleMesh models (Tds, Dcel) against the concept's semantics: each mutation
// on small hand-built meshes with the exact faces expected, connectivity validated after
// every mutation, and random sequences of mutations applied to both structures that must
// keep them holding the same faces. Purely topological: vertex ids are labels.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "mesh_validate.hpp"
#include "meshstep/huge_pages.hpp"
#include "meshstep/mesh/concept.hpp"
#include "meshstep/mesh/dcel.hpp"
#include "meshstep/mesh/tds.hpp"
#include "meshstep/release.hpp"

namespace meshstep {
namespace {

static_assert(TriangleMesh<Tds>);
static_assert(TriangleMesh<Dcel>);

constexpr VertexId I = kInfiniteVertex;
using Triple = std::array<std::uint32_t, 3>;
using FaceSet = std::vector<Triple>;

Triple canonical(Triple t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

FaceSet faces_of(std::vector<Triple> ts) {
  for (Triple& t : ts) t = canonical(t);
  std::sort(ts.begin(), ts.end());
  return ts;
}

template <class M>
Triple triple(const M& m, FaceId f) {
  const HalfEdge h = m.half_edge(f);
  return {m.origin(h), m.dest(h), m.apex(h)};
}

// The live face holding these three vertices in this cyclic order, or kNone.
template <class M>
FaceId find_face(const M& m, const Triple& t) {
  const Triple want = canonical(t);
  for (FaceId f = 0; f < m.face_capacity(); ++f)
    if (m.is_live(f) && canonical(triple(m, f)) == want) return f;
  return kNone;
}

// The half-edge u -> w of a live face, or kNone.
template <class M>
HalfEdge find_half_edge(const M& m, VertexId u, VertexId w) {
  for (FaceId f = 0; f < m.face_capacity(); ++f) {
    if (!m.is_live(f)) continue;
    HalfEdge h = m.half_edge(f);
    for (int i = 0; i < 3; ++i, h = m.next(h))
      if (m.origin(h) == u && m.dest(h) == w) return h;
  }
  return kNone;
}

// Undirected constrained edges seen from live faces (smaller id first), sorted.
template <class M>
std::vector<std::pair<VertexId, VertexId>> constrained_edges(const M& m) {
  std::set<std::pair<VertexId, VertexId>> out;
  for (FaceId f = 0; f < m.face_capacity(); ++f) {
    if (!m.is_live(f)) continue;
    HalfEdge h = m.half_edge(f);
    for (int i = 0; i < 3; ++i, h = m.next(h))
      if (m.is_constrained(h))
        out.insert(std::minmax(m.origin(h), m.dest(h)));
  }
  return {out.begin(), out.end()};
}

template <class M>
std::size_t boundary_half_edges(const M& m) {
  std::size_t n = 0;
  for (FaceId f = 0; f < m.face_capacity(); ++f) {
    if (!m.is_live(f)) continue;
    HalfEdge h = m.half_edge(f);
    for (int i = 0; i < 3; ++i, h = m.next(h)) n += m.twin(h) == kNone;
  }
  return n;
}

std::string join(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& l : lines) s += "\n  " + l;
  return s;
}

#define EXPECT_VALID(m)                                                   \
  do {                                                                    \
    const auto problems_ = validate_connectivity(m);                      \
    EXPECT_TRUE(problems_.empty()) << join(problems_);                    \
  } while (0)
#define ASSERT_VALID(m)                                                   \
  do {                                                                    \
    const auto problems_ = validate_connectivity(m);                      \
    ASSERT_TRUE(problems_.empty()) << join(problems_);                    \
  } while (0)

// The sphere (0, 1, 2) + ghosts, with room for `vertices` finite vertex ids.
template <class M>
HalfEdge make_sphere(M& m, std::size_t vertices, VertexId outer = I) {
  m.set_vertex_count(vertices);
  return m.init_sphere(0, 1, 2, outer);
}

struct StructureName {
  template <class T>
  static std::string GetName(int) {
    return T::kName;
  }
};

template <class M>
class MeshStructures : public ::testing::Test {};
using Structures = ::testing::Types<Tds, Dcel>;
// A closed surface of vertices 0..n-1 and I: the first triangle, then every vertex split
// into a face chosen at random (not Delaunay: only the structure is under test).
template <class M>
void grow_at_random(M& m, VertexId n, unsigned seed) {
  std::mt19937 rng(seed);
  m.init_sphere(0, 1, 2, I);
  for (VertexId v = 3; v < n; ++v) {
    FaceId f;
    do f = static_cast<FaceId>(rng() % m.face_capacity());
    while (!m.is_live(f));
    m.split_face(f, v);
  }
}

TYPED_TEST_SUITE(MeshStructures, Structures, StructureName);

// ---------------------------------------------------------------------------------------
// The validator itself: each kind of corruption, injected by hiding one member of a real
// structure, must be reported, and the intact structure must not be.

enum class Fault { none, twin, constraint, vertex_half_edge, next, face_count, face, corner, constraint_mask };

template <class M>
struct Faulty : M {
  Fault fault = Fault::none;
  HalfEdge target = kNone;
  VertexId target_vertex = kNone;

  HalfEdge twin(HalfEdge h) const {
    // Points h at a half-edge of its own face: twin(twin(h)) != h and origins disagree.
    return fault == Fault::twin && h == target ? M::next(h) : M::twin(h);
  }
  bool is_constrained(HalfEdge h) const {
    return fault == Fault::constraint && h == target ? !M::is_constrained(h)
                                                     : M::is_constrained(h);
  }
  HalfEdge vertex_half_edge(VertexId v) const {
    const HalfEdge h = M::vertex_half_edge(v);
    return fault == Fault::vertex_half_edge && v == target_vertex ? M::next(h) : h;
  }
  HalfEdge next(HalfEdge h) const { return fault == Fault::next && h == target ? h : M::next(h); }
  FaceId face(HalfEdge h) const {
    return fault == Fault::face && h == target ? M::face(M::twin(h)) : M::face(h);
  }
  std::size_t face_count() const { return M::face_count() + (fault == Fault::face_count); }
  std::uint32_t corner(HalfEdge h) const {
    return fault == Fault::corner && h == target ? (M::corner(h) + 1) % 3 : M::corner(h);
  }
  std::uint32_t constraint_mask(FaceId f) const {
    return fault == Fault::constraint_mask && f == M::face(target) ? M::constraint_mask(f) ^ 4u
                                                                    : M::constraint_mask(f);
  }
};

TYPED_TEST(MeshStructures, ValidatorReportsEachKindOfCorruption) {
  static_assert(TriangleMesh<Faulty<TypeParam>>);
  Faulty<TypeParam> m;
  const HalfEdge h = make_sphere(m, 4);
  m.split_face(m.face(h), 3);
  EXPECT_TRUE(validate_connectivity(m).empty()) << join(validate_connectivity(m));

  const HalfEdge h01 = find_half_edge(m, 0, 1);
  for (const Fault fault : {Fault::twin, Fault::constraint, Fault::vertex_half_edge, Fault::next,
                            Fault::face_count, Fault::face, Fault::corner, Fault::constraint_mask}) {
    m.fault = fault;
    m.target = h01;
    m.target_vertex = 3;
    EXPECT_FALSE(validate_connectivity(m).empty()) << "fault " << static_cast<int>(fault);
  }
  m.fault = Fault::none;
  EXPECT_TRUE(validate_connectivity(m).empty());
}

TYPED_TEST(MeshStructures, FaceSetIsCanonical) {
  TypeParam m;
  make_sphere(m, 3);
  // Rotated to the smallest id, orientation kept ((1,0,I) becomes (0,I,1), not (0,1,I)).
  EXPECT_EQ(face_set(m), (FaceSet{{0, 1, 2}, {0, 2, I}, {0, I, 1}, {1, I, 2}}));
}

// ---------------------------------------------------------------------------------------
// One mutation at a time.

TYPED_TEST(MeshStructures, InitSphereMakesFourFacesWithTwins) {
  for (const VertexId outer : {I, VertexId{3}}) {
    SCOPED_TRACE(outer);
    TypeParam m;
    const HalfEdge h = make_sphere(m, 4, outer);
    EXPECT_EQ(m.face_count(), 4u);
    EXPECT_EQ(m.origin(h), 0u);
    EXPECT_EQ(m.dest(h), 1u);
    EXPECT_EQ(m.apex(h), 2u);
    EXPECT_EQ(face_set(m), faces_of({{0, 1, 2}, {1, 0, outer}, {2, 1, outer}, {0, 2, outer}}));
    ASSERT_VALID(m);
    // Closed: every half-edge has the reverse half-edge as twin, in the face across.
    EXPECT_EQ(boundary_half_edges(m), 0u);
    for (const auto& [u, w, across] : std::vector<Triple>{
             {0, 1, outer}, {1, 2, outer}, {2, 0, outer}, {1, 0, 2}, {0, outer, 2}}) {
      const HalfEdge e = find_half_edge(m, u, w);
      ASSERT_NE(e, kNone);
      const HalfEdge t = m.twin(e);
      ASSERT_NE(t, kNone);
      EXPECT_EQ(m.origin(t), w);
      EXPECT_EQ(m.dest(t), u);
      EXPECT_EQ(m.apex(t), across);
    }
    EXPECT_EQ(m.origin(m.vertex_half_edge(outer)), outer);
    EXPECT_TRUE(constrained_edges(m).empty());
  }
}

TYPED_TEST(MeshStructures, SplitFace) {
  TypeParam m;
  const HalfEdge h = make_sphere(m, 5);
  const HalfEdge out = m.split_face(m.face(h), 3);
  EXPECT_EQ(m.origin(out), 3u);
  EXPECT_EQ(m.face_count(), 6u);
  EXPECT_EQ(face_set(m), faces_of({{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {1, 0, I}, {2, 1, I},
                                   {0, 2, I}}));
  ASSERT_VALID(m);
  // A ghost face splits the same way (a vertex "outside the hull").
  const HalfEdge g = m.split_face(find_face(m, {1, 0, I}), 4);
  EXPECT_EQ(m.origin(g), 4u);
  EXPECT_EQ(face_set(m), faces_of({{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {1, 0, 4}, {0, I, 4},
                                   {I, 1, 4}, {2, 1, I}, {0, 2, I}}));
  ASSERT_VALID(m);
  EXPECT_EQ(boundary_half_edges(m), 0u);
}

TYPED_TEST(MeshStructures, SplitInteriorEdge) {
  TypeParam m;
  make_sphere(m, 4);
  const HalfEdge out = m.split_edge(find_half_edge(m, 0, 1), 3);
  EXPECT_EQ(m.origin(out), 3u);
  EXPECT_EQ(m.dest(out), 1u);
  EXPECT_EQ(m.face_count(), 6u);
  EXPECT_EQ(face_set(m), faces_of({{0, 3, 2}, {3, 1, 2}, {1, 3, I}, {3, 0, I}, {2, 1, I},
                                   {0, 2, I}}));
  ASSERT_VALID(m);
  EXPECT_TRUE(constrained_edges(m).empty());
}

TYPED_TEST(MeshStructures, SplitConstrainedEdgeKeepsBothHalvesConstrained) {
  TypeParam m;
  make_sphere(m, 4);
  m.set_constrained(find_half_edge(m, 1, 0), true);  // from the ghost side
  ASSERT_VALID(m);
  EXPECT_TRUE(m.is_constrained(find_half_edge(m, 0, 1)));
  EXPECT_TRUE(m.is_constrained(find_half_edge(m, 1, 0)));
  m.split_edge(find_half_edge(m, 0, 1), 3);
  ASSERT_VALID(m);
  using E = std::pair<VertexId, VertexId>;
  EXPECT_EQ(constrained_edges(m), (std::vector<E>{{0, 3}, {1, 3}}));
  // Both sides of both halves; the new edges to the apexes (3-2, 3-I) stay free.
  for (const auto& [u, w] : std::vector<E>{{0, 3}, {3, 0}, {3, 1}, {1, 3}})
    EXPECT_TRUE(m.is_constrained(find_half_edge(m, u, w))) << u << "->" << w;
  EXPECT_FALSE(m.is_constrained(find_half_edge(m, 3, 2)));
  EXPECT_FALSE(m.is_constrained(find_half_edge(m, 3, I)));
  // Clearing works on both sides too.
  m.set_constrained(find_half_edge(m, 3, 1), false);
  EXPECT_EQ(constrained_edges(m), (std::vector<E>{{0, 3}}));
  ASSERT_VALID(m);
}

TYPED_TEST(MeshStructures, SplitBoundaryEdge) {
  for (const bool constrained : {false, true}) {
    SCOPED_TRACE(constrained);
    TypeParam m;
    make_sphere(m, 4);
    m.set_constrained(find_half_edge(m, 0, 1), constrained);
    m.remove_face(find_face(m, {1, 0, I}));
    m.rebuild_vertex_half_edges();
    ASSERT_VALID(m);
    const HalfEdge h = find_half_edge(m, 0, 1);
    ASSERT_EQ(m.twin(h), kNone);
    EXPECT_EQ(m.is_constrained(h), constrained);  // the flag outlives the other side

    const HalfEdge out = m.split_edge(h, 3);
    EXPECT_EQ(m.origin(out), 3u);
    EXPECT_EQ(m.dest(out), 1u);
    EXPECT_EQ(m.face_count(), 4u);
    EXPECT_EQ(face_set(m), faces_of({{0, 3, 2}, {3, 1, 2}, {2, 1, I}, {0, 2, I}}));
    ASSERT_VALID(m);
    const HalfEdge a3 = find_half_edge(m, 0, 3);
    EXPECT_EQ(m.twin(a3), kNone);
    EXPECT_EQ(m.twin(out), kNone);
    EXPECT_EQ(m.is_constrained(a3), constrained);
    EXPECT_EQ(m.is_constrained(out), constrained);
    EXPECT_FALSE(m.is_constrained(find_half_edge(m, 3, 2)));
    // The boundary is now 0->3->1 (2 half-edges) plus the half-edges that faced the
    // removed ghost from its neighbours: I->0 and 1->I.
    EXPECT_EQ(boundary_half_edges(m), 4u);
  }
}

TYPED_TEST(MeshStructures, MergeStarUndoesSplitFace) {
  TypeParam m;
  const HalfEdge h = make_sphere(m, 5);
  const FaceSet before = face_set(m);
  // Flags on the ring survive the merge; the spokes go with the vertex.
  m.set_constrained(h, true);  // 0 -> 1
  const HalfEdge out = m.split_face(m.face(h), 3);
  m.set_constrained(out, true);  // a spoke: 3 -> 0
  EXPECT_EQ(m.face_count(), 6u);
  const HalfEdge merged = m.merge_star(find_half_edge(m, 3, 1));
  EXPECT_EQ(face_set(m), before);
  EXPECT_EQ(m.face_count(), 4u);
  EXPECT_EQ(canonical(triple(m, m.face(merged))), (Triple{0, 1, 2}));
  EXPECT_EQ(m.vertex_half_edge(3), kNone);
  EXPECT_EQ(constrained_edges(m), (std::vector<std::pair<VertexId, VertexId>>{{0, 1}}));
  ASSERT_VALID(m);
  // The slots the merge freed are taken again.
  m.split_face(m.face(merged), 4);
  EXPECT_EQ(m.face_count(), 6u);
  EXPECT_EQ(m.face_capacity(), 6u);
  ASSERT_VALID(m);
}

TYPED_TEST(MeshStructures, MergeStarAfterAFlipAroundTheVertex) {
  // 3 splits face (0, 1, 2), then 5 splits edge 3-0: 5 has neighbours 0, 1, 3, 2. Flipping
  // 5-1 (to 0-3) leaves it degree 3, and the merge removes it: the vertex-removal sequence.
  TypeParam m;
  const HalfEdge h = make_sphere(m, 6);
  m.split_face(m.face(h), 3);
  m.split_edge(find_half_edge(m, 3, 0), 5);
  const FaceSet before = face_set(m);
  m.flip(find_half_edge(m, 5, 1));
  ASSERT_VALID(m);
  const HalfEdge out = m.merge_star(find_half_edge(m, 5, 0));
  ASSERT_VALID(m);
  EXPECT_EQ(m.face_count(), before.size() - 2);
  EXPECT_EQ(face_set(m), faces_of({{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {1, 0, I}, {2, 1, I}, {0, 2, I}}));
  EXPECT_EQ(canonical(triple(m, m.face(out))), canonical({2, 0, 3}));
}

TYPED_TEST(MeshStructures, FlipAndFlipBack) {
  TypeParam m;
  const HalfEdge h = make_sphere(m, 4);
  m.split_face(m.face(h), 3);
  const FaceSet before = face_set(m);
  // Outer edges of the quadrilateral around 0-1 keep their flags; 1-3 is one of them.
  // The flipped edge's flag does not pass to the new diagonal: that is another edge.
  m.set_constrained(find_half_edge(m, 1, 3), true);
  m.set_constrained(find_half_edge(m, 0, 1), true);

  const HalfEdge e = find_half_edge(m, 0, 1);  // in (0, 1, 3); across: (1, 0, I)
  const HalfEdge d = m.flip(e);
  EXPECT_EQ(m.origin(d), 3u);  // apex of e
  EXPECT_EQ(m.dest(d), I);     // apex of its twin
  EXPECT_EQ(m.face_count(), 6u);
  EXPECT_EQ(face_set(m), faces_of({{3, 0, I}, {I, 1, 3}, {1, 2, 3}, {2, 0, 3}, {2, 1, I},
                                   {0, 2, I}}));
  ASSERT_VALID(m);
  EXPECT_EQ(find_half_edge(m, 0, 1), kNone);
  EXPECT_FALSE(m.is_constrained(d));
  EXPECT_FALSE(m.is_constrained(m.twin(d)));
  EXPECT_TRUE(m.is_constrained(find_half_edge(m, 1, 3)));
  EXPECT_TRUE(m.is_constrained(find_half_edge(m, 3, 1)));

  const HalfEdge back = m.flip(d);
  EXPECT_EQ(m.origin(back), 1u);
  EXPECT_EQ(m.dest(back), 0u);
  EXPECT_EQ(face_set(m), before);
  ASSERT_VALID(m);
  using E = std::pair<VertexId, VertexId>;
  EXPECT_EQ(constrained_edges(m), (std::vector<E>{{1, 3}}));
}

// A hexagonal cavity: face (0, 4, 3) and its three neighbours, of a mesh where vertex 3 is
// surrounded by 0, 4, 1, 5, 2, 6.
template <class M>
void make_hexagon_mesh(M& m) {
  const HalfEdge h = make_sphere(m, 8);
  m.split_face(m.face(h), 3);
  m.split_edge(find_half_edge(m, 0, 1), 4);
  m.split_edge(find_half_edge(m, 1, 2), 5);
  m.split_edge(find_half_edge(m, 2, 0), 6);
}

struct Cavity {
  std::vector<HalfEdge> ring;
  std::vector<FaceId> faces;
};

// Face f and its neighbours across the edges selected by `mask` (bit i: the i-th edge of f
// counting counterclockwise from the one leaving vertex `first`, so that both structures
// pick the same edges): the boundary ring, counterclockwise, and the faces, f first.
template <class M>
Cavity cavity_around(const M& m, FaceId f, VertexId first, unsigned mask) {
  Cavity c;
  HalfEdge h = m.half_edge(f);
  while (m.origin(h) != first) h = m.next(h);
  c.faces.push_back(f);
  for (int i = 0; i < 3; ++i, h = m.next(h)) {
    const HalfEdge t = m.twin(h);
    if ((mask >> i & 1u) && t != kNone) {
      c.ring.push_back(m.next(t));
      c.ring.push_back(m.prev(t));
      c.faces.push_back(m.face(t));
    } else {
      c.ring.push_back(h);
    }
  }
  return c;
}

TYPED_TEST(MeshStructures, StarCavityOfSeveralFaces) {
  TypeParam m;
  make_hexagon_mesh(m);
  ASSERT_VALID(m);
  EXPECT_EQ(m.face_count(), 12u);
  m.set_constrained(find_half_edge(m, 4, 1), true);  // a ring edge
  m.set_constrained(find_half_edge(m, 4, 3), true);  // an interior edge: it disappears
  const std::size_t capacity = m.face_capacity();

  const FaceId f = find_face(m, {0, 4, 3});
  ASSERT_NE(f, kNone);
  const Cavity c = cavity_around(m, f, 0, 0b111);
  ASSERT_EQ(c.ring.size(), 6u);
  ASSERT_EQ(c.faces.size(), 4u);
  std::vector<VertexId> ring_vertices;
  for (const HalfEdge r : c.ring) ring_vertices.push_back(m.origin(r));
  ASSERT_EQ(ring_vertices, (std::vector<VertexId>{0, I, 4, 1, 3, 6}));

  const FaceSet before = face_set(m);
  const HalfEdge out = m.star_cavity(c.ring, c.faces, 7);
  EXPECT_EQ(m.origin(out), 7u);
  EXPECT_EQ(m.face_count(), 14u);
  // 4 faces freed and 6 made: the 4 slots are reused, so exactly 2 more slots at most.
  EXPECT_LE(m.face_capacity(), capacity + 2);
  FaceSet expected;
  for (const Triple& t : before)
    if (t != canonical({0, 4, 3}) && t != canonical({4, 0, I}) && t != canonical({4, 1, 3}) &&
        t != canonical({6, 0, 3}))
      expected.push_back(t);
  for (const Triple& t : std::vector<Triple>{
           {0, I, 7}, {I, 4, 7}, {4, 1, 7}, {1, 3, 7}, {3, 6, 7}, {6, 0, 7}})
    expected.push_back(canonical(t));
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(face_set(m), expected);
  ASSERT_VALID(m);
  using E = std::pair<VertexId, VertexId>;
  EXPECT_EQ(constrained_edges(m), (std::vector<E>{{1, 4}}));
  EXPECT_EQ(boundary_half_edges(m), 0u);
}

TYPED_TEST(MeshStructures, StarCavityOfOneFaceIsASplit) {
  TypeParam a, b;
  const HalfEdge ha = make_sphere(a, 4), hb = make_sphere(b, 4);
  a.split_face(a.face(ha), 3);
  const Cavity c = cavity_around(b, b.face(hb), 0, 0);
  const HalfEdge out = b.star_cavity(c.ring, c.faces, 3);
  EXPECT_EQ(b.origin(out), 3u);
  ASSERT_VALID(b);
  EXPECT_EQ(face_set(a), face_set(b));
}

TYPED_TEST(MeshStructures, RemoveFacesThenRebuild) {
  TypeParam m;
  const HalfEdge h = make_sphere(m, 5);
  m.split_face(m.face(h), 3);
  const std::size_t capacity = m.face_capacity();
  // Remove every ghost face: what is left is the disk 0, 1, 2 around 3.
  std::vector<FaceId> ghosts;
  for (FaceId f = 0; f < m.face_capacity(); ++f) {
    if (!m.is_live(f)) continue;
    const Triple t = triple(m, f);
    if (std::find(t.begin(), t.end(), I) != t.end()) ghosts.push_back(f);
  }
  ASSERT_EQ(ghosts.size(), 3u);
  for (const FaceId f : ghosts) {
    m.remove_face(f);
    EXPECT_FALSE(m.is_live(f));
    // Until the rebuild only vertex_half_edge may be stale; everything else must hold.
    const auto problems = validate_connectivity(m, false);
    ASSERT_TRUE(problems.empty()) << join(problems);
  }
  m.rebuild_vertex_half_edges();
  ASSERT_VALID(m);
  EXPECT_EQ(m.face_count(), 3u);
  EXPECT_EQ(face_set(m), faces_of({{0, 1, 3}, {1, 2, 3}, {2, 0, 3}}));
  EXPECT_EQ(boundary_half_edges(m), 3u);
  for (const VertexId v : {0u, 1u, 2u, 3u}) {
    const HalfEdge e = m.vertex_half_edge(v);
    ASSERT_NE(e, kNone);
    EXPECT_EQ(m.origin(e), v);
    EXPECT_TRUE(m.is_live(m.face(e)));
  }
  // The freed slots are reused.
  m.split_face(find_face(m, {0, 1, 3}), 4);
  EXPECT_EQ(m.face_capacity(), capacity);
  ASSERT_VALID(m);
  // Remove everything.
  for (FaceId f = 0; f < m.face_capacity(); ++f)
    if (m.is_live(f)) m.remove_face(f);
  m.rebuild_vertex_half_edges();
  EXPECT_EQ(m.face_count(), 0u);
  EXPECT_TRUE(face_set(m).empty());
  EXPECT_EQ(m.vertex_half_edge(0), kNone);
  EXPECT_EQ(m.vertex_half_edge(I), kNone);
}

// Before a conversion, a mesh gives back what only crossing edges needs; its faces must
// read the same afterwards, with a boundary (carved) and freed slots among them.
TYPED_TEST(MeshStructures, DropAdjacencyKeepsEveryFaceAndFreesMemory) {
  constexpr VertexId n = 2000;
  TypeParam m;
  m.reserve(n, 2 * n);
  m.set_vertex_count(n);
  grow_at_random(m, n, 11);
  for (FaceId f = 0; f < m.face_capacity(); ++f)
    if (m.is_live(f) && (f % 7 == 0 || std::ranges::count(triple(m, f), I) > 0)) m.remove_face(f);
  const auto faces = face_set(m);
  const std::size_t count = m.face_count(), capacity = m.face_capacity(), before = m.memory_bytes();
  m.drop_adjacency();
  EXPECT_EQ(face_set(m), faces);
  EXPECT_EQ(m.face_count(), count);
  EXPECT_EQ(m.face_capacity(), capacity);
  for (FaceId f = 0; f < m.face_capacity(); ++f) {
    if (!m.is_live(f)) continue;
    const HalfEdge h = m.half_edge(f);
    EXPECT_EQ(m.prev(m.next(h)), h);
    EXPECT_EQ(m.next(m.next(m.next(h))), h);
    EXPECT_EQ(m.origin(m.next(h)), m.dest(h));
  }
  // Tds: the twins and vertex half-edges (more than half); Dcel: face(h) and the vertex
  // half-edges (about a third).
  EXPECT_LT(m.memory_bytes(), before * 3 / 4) << before;
}

// The stale-handle idiom of the algorithms: after a mutation, is_live(face(h)) on an old
// handle must be answerable (and false when h no longer names a half-edge of a face).
TYPED_TEST(MeshStructures, StaleHandlesAreSafeToTest) {
  TypeParam m;
  make_hexagon_mesh(m);
  std::vector<HalfEdge> old;
  for (FaceId f = 0; f < m.face_capacity(); ++f) {
    if (!m.is_live(f)) continue;
    HalfEdge h = m.half_edge(f);
    for (int i = 0; i < 3; ++i, h = m.next(h)) old.push_back(h);
  }
  const FaceId f = find_face(m, {0, 4, 3});
  const Cavity c = cavity_around(m, f, 0, 0b111);
  m.star_cavity(c.ring, c.faces, 7);
  m.remove_face(find_face(m, {0, I, 7}));
  m.rebuild_vertex_half_edges();
  std::size_t live = 0;
  for (const HalfEdge h : old) {
    if (!m.is_live(m.face(h))) continue;
    ++live;
    EXPECT_NE(m.origin(h), kNone);
  }
  EXPECT_GT(live, 0u);
}

// ---------------------------------------------------------------------------------------
// Random sequences applied to both structures.

struct Op {
  enum Kind { split_face, split_edge, flip, star_cavity, remove_face, set_constrained, merge_star } kind;
  Triple face;    // canonical vertex triple of the face acted on
  int edge = 0;   // edge i runs face[i] -> face[(i + 1) % 3]
  unsigned mask = 0;
  VertexId v = kNone;
  bool flag = false;
};

template <class M>
HalfEdge edge_of(const M& m, const Op& op) {
  const FaceId f = find_face(m, op.face);
  if (f == kNone) return kNone;
  HalfEdge h = m.half_edge(f);
  while (m.origin(h) != op.face[op.edge]) h = m.next(h);
  return h;
}

// Applies op; returns (origin, dest) of the half-edge the mutation returned, or kNone pair.
template <class M>
std::pair<VertexId, VertexId> apply(M& m, const Op& op) {
  const FaceId f = find_face(m, op.face);
  if (f == kNone) return {kNone, kNone};
  HalfEdge out = kNone;
  switch (op.kind) {
    case Op::split_face: out = m.split_face(f, op.v); break;
    case Op::split_edge: out = m.split_edge(edge_of(m, op), op.v); break;
    case Op::flip: out = m.flip(edge_of(m, op)); break;
    case Op::star_cavity: {
      const Cavity c = cavity_around(m, f, op.face[0], op.mask);
      out = m.star_cavity(c.ring, c.faces, op.v);
      break;
    }
    case Op::remove_face:
      m.remove_face(f);  // the caller validates, then rebuilds vertex half-edges
      return {kNone, kNone};
    case Op::set_constrained:
      m.set_constrained(edge_of(m, op), op.flag);
      return {kNone, kNone};
    case Op::merge_star: out = m.merge_star(edge_of(m, op)); break;
  }
  return {m.origin(out), m.dest(out)};
}

// Chooses an operation valid on `m` (read through the Tds copy), or returns false.
bool choose(const Tds& m, std::mt19937& rng, VertexId next_vertex, bool allow_remove, Op& op) {
  const FaceSet faces = face_set(m);
  op = Op{};
  op.face = faces[rng() % faces.size()];
  op.edge = static_cast<int>(rng() % 3);
  op.v = next_vertex;
  const unsigned r = rng() % 100;
  const HalfEdge h = edge_of(m, op);
  if (r < 20) {
    op.kind = Op::split_face;
  } else if (r < 40) {
    op.kind = Op::split_edge;
  } else if (r < 70) {
    // Flip only when the result stays a simplicial complex: the two apexes differ and are
    // not already joined (else the flip would duplicate an edge).
    op.kind = Op::flip;
    const HalfEdge t = m.twin(h);
    if (t == kNone) return false;
    const VertexId c = m.apex(h), d = m.apex(t);
    if (c == d || find_half_edge(m, c, d) != kNone || find_half_edge(m, d, c) != kNone)
      return false;
  } else if (r < 75) {
    // A vertex of degree 3 with no boundary round it, whose merged face is not already
    // there reversed (a tetrahedron would fold flat); searched from a random face, since
    // a random edge rarely leaves one.
    op.kind = Op::merge_star;
    const auto mergeable = [&](HalfEdge e) {
      HalfEdge g = e;
      for (int i = 0; i < 3; ++i) {
        if (m.twin(m.prev(g)) == kNone) return false;
        g = m.twin(m.prev(g));
      }
      return g == e && find_face(m, {m.apex(m.twin(e)), m.apex(e), m.dest(e)}) == kNone;
    };
    const std::size_t start = rng() % faces.size();
    for (std::size_t i = 0; i < faces.size(); ++i) {
      op.face = faces[(start + i) % faces.size()];
      for (op.edge = 0; op.edge < 3; ++op.edge)
        if (mergeable(edge_of(m, op))) return true;
    }
    return false;
  } else if (r < 90) {
    // A face and some neighbours form a disk without interior vertices exactly when the
    // ring's vertices are distinct.
    op.kind = Op::star_cavity;
    op.mask = rng() % 8;
    const FaceId f = find_face(m, op.face);
    const Cavity c = cavity_around(m, f, op.face[0], op.mask);
    if (c.faces.size() != 1 + static_cast<std::size_t>(std::popcount(op.mask))) return false;
    std::vector<VertexId> vs;
    for (const HalfEdge e : c.ring) vs.push_back(m.origin(e));
    std::sort(vs.begin(), vs.end());
    if (std::adjacent_find(vs.begin(), vs.end()) != vs.end()) return false;
  } else if (r < 95) {
    op.kind = Op::set_constrained;
    op.flag = rng() % 2 == 0;
  } else {
    if (!allow_remove || faces.size() < 12) return false;
    op.kind = Op::remove_face;
  }
  return true;
}

void run_random_episode(unsigned seed, int operations, VertexId outer, bool allow_remove) {
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  const std::size_t vertex_ids = 5 + static_cast<std::size_t>(operations);
  Tds a;
  Dcel b;
  a.set_vertex_count(vertex_ids);
  b.set_vertex_count(vertex_ids);
  a.init_sphere(0, 1, 2, outer);
  b.init_sphere(0, 1, 2, outer);
  VertexId next_vertex = 4;
  int done = 0, attempts = 0;
  int counts[7] = {};
  std::size_t merged = 0;
  while (done < operations && attempts < 20 * operations) {
    ++attempts;
    Op op;
    if (!choose(a, rng, next_vertex, allow_remove, op)) continue;
    ++done;
    ++counts[op.kind];
    SCOPED_TRACE("operation " + std::to_string(done) + " kind " + std::to_string(op.kind));
    const auto ra = apply(a, op);
    const auto rb = apply(b, op);
    if (op.kind == Op::remove_face) {
      for (const auto& problems : {validate_connectivity(a, false), validate_connectivity(b, false)})
        ASSERT_TRUE(problems.empty()) << join(problems);
      a.rebuild_vertex_half_edges();
      b.rebuild_vertex_half_edges();
    }
    ASSERT_VALID(a);
    ASSERT_VALID(b);
    ASSERT_EQ(face_set(a), face_set(b));
    ASSERT_EQ(constrained_edges(a), constrained_edges(b));
    ASSERT_EQ(a.face_count(), b.face_count());
    // split_face and star_cavity promise only some half-edge leaving v; split_edge and
    // flip name theirs exactly.
    switch (op.kind) {
      case Op::split_face:
      case Op::star_cavity:
        ASSERT_EQ(ra.first, op.v);
        ASSERT_EQ(rb.first, op.v);
        break;
      case Op::split_edge:
        ASSERT_EQ(ra, std::make_pair(op.v, op.face[(op.edge + 1) % 3]));
        ASSERT_EQ(rb, ra);
        break;
      case Op::flip:
        // apex -> apex of the twin, the same vertices in both; the old edge is gone.
        ASSERT_EQ(rb, ra);
        ASSERT_EQ(ra.first, op.face[(op.edge + 2) % 3]);
        ASSERT_EQ(find_half_edge(a, op.face[op.edge], op.face[(op.edge + 1) % 3]), kNone);
        break;
      default: break;
    }
    if (op.kind == Op::split_face || op.kind == Op::split_edge || op.kind == Op::star_cavity)
      ++next_vertex;
    if (op.kind == Op::merge_star) {
      ++merged;
      ASSERT_EQ(a.vertex_half_edge(op.face[op.edge]), kNone);
      ASSERT_EQ(b.vertex_half_edge(op.face[op.edge]), kNone);
    }
    if (!allow_remove) {
      // A closed surface: Euler gives F = 2V - 4 and E = 3V - 6, V counting the outer one.
      const std::size_t vertices = next_vertex - merged;
      ASSERT_EQ(b.face_count(), 2 * vertices - 4);
      ASSERT_EQ(b.edge_count(), 3 * vertices - 6);
      ASSERT_EQ(boundary_half_edges(b), 0u);
    }
  }
  EXPECT_EQ(done, operations);
  // Every kind was exercised.
  for (const int k : {Op::split_face, Op::split_edge, Op::flip, Op::star_cavity,
                      Op::set_constrained, Op::merge_star})
    EXPECT_GT(counts[k], 0) << "kind " << k;
  if (allow_remove) {
    EXPECT_GT(counts[Op::remove_face], 0);
  }
}

// Many short episodes rather than a few long ones: every step validates the whole mesh,
// so the cost grows with the square of an episode's length. 16 x 250 operations in all.
// Odd seeds close the sphere with kInfiniteVertex, even ones with an ordinary vertex.
TEST(MeshStructuresRandom, TdsAndDcelStayIdenticalOnClosedSurfaces) {
  for (unsigned seed = 1; seed <= 8; ++seed)
    run_random_episode(seed, 250, seed % 2 ? I : VertexId{3}, false);
}

TEST(MeshStructuresRandom, TdsAndDcelStayIdenticalWithBoundaries) {
  for (unsigned seed = 11; seed <= 18; ++seed)
    run_random_episode(seed, 250, seed % 2 ? I : VertexId{3}, true);
}

// ---------------------------------------------------------------------------------------
// Dcel specifics: pair reuse, no growth in steady state, size.

TEST(Release, GivesTheMemoryBack) {
  std::vector<double> v(1000, 1.0);
  release(v);
  EXPECT_TRUE(v.empty());
  EXPECT_EQ(v.capacity(), 0u);  // `v = {}` would keep all 1000
}

TEST(HugePages, GrowHugeDoublesAndKeepsTheElements) {
  std::vector<std::uint32_t> v;
  std::size_t reallocations = 0;
  for (std::uint32_t i = 0; i < 100000; ++i) {
    const std::size_t before = v.capacity();
    grow_huge(v);
    reallocations += v.capacity() != before;
    ASSERT_GT(v.capacity(), v.size());
    v.push_back(i);
  }
  EXPECT_LE(reallocations, 18u);  // geometric: about log2(100000) + 1
  for (std::uint32_t i = 0; i < v.size(); ++i) ASSERT_EQ(v[i], i);
  const std::size_t capacity = v.capacity();
  grow_huge(v, capacity - v.size());  // room enough already
  EXPECT_EQ(v.capacity(), capacity);
}

TEST(Dcel, FlipReusesTheEdgePair) {
  Dcel m;
  const HalfEdge h = make_sphere(m, 4);
  m.split_face(m.face(h), 3);
  const std::size_t edges = m.edge_capacity(), bytes = m.memory_bytes();
  const HalfEdge e = find_half_edge(m, 0, 1);
  const HalfEdge d = m.flip(e);
  EXPECT_EQ(d >> 1, e >> 1);  // the same pair, relinked
  EXPECT_EQ(m.edge_capacity(), edges);
  EXPECT_EQ(m.memory_bytes(), bytes);
}

TEST(Dcel, StarCavityTakesSpokesFromTheFreedInteriorEdges) {
  Dcel m;
  make_hexagon_mesh(m);
  const std::size_t edges = m.edge_count();
  ASSERT_EQ(m.edge_capacity(), edges);  // nothing freed yet
  ASSERT_EQ(edges, 3u * 8 - 6);         // 0..6 and I
  const Cavity c = cavity_around(m, find_face(m, {0, 4, 3}), 0, 0b111);
  m.star_cavity(c.ring, c.faces, 7);
  // 6 spokes replace 3 interior edges: 3 pairs reused, 3 new.
  EXPECT_EQ(m.edge_count(), edges + 3);
  EXPECT_EQ(m.edge_capacity(), edges + 3);
}

TEST(Dcel, RemoveFaceFreesPairsWithNoFaceLeft) {
  Dcel m;
  const HalfEdge h = make_sphere(m, 5);
  m.split_face(m.face(h), 3);
  ASSERT_EQ(m.edge_count(), 9u);
  const FaceId g = find_face(m, {1, 0, I});
  m.remove_face(g);
  EXPECT_EQ(m.edge_count(), 9u);  // each of its edges still has a face on the other side
  m.remove_face(find_face(m, {0, 2, I}));
  EXPECT_EQ(m.edge_count(), 8u);  // 0-I lost both sides
  m.rebuild_vertex_half_edges();
  ASSERT_VALID(m);
  // Growth after removal takes the freed pair and face slots first.
  const std::size_t edge_capacity = m.edge_capacity(), face_capacity = m.face_capacity();
  m.split_face(find_face(m, {0, 1, 3}), 4);  // 2 faces, 3 pairs
  EXPECT_EQ(m.face_capacity(), face_capacity);
  EXPECT_EQ(m.edge_capacity(), edge_capacity + 2);
  ASSERT_VALID(m);
}

TEST(Dcel, AtMostNinetyBytesPerVertexAndNoGrowthAfterReserve) {
  constexpr std::size_t n = 20000;
  Dcel m;
  m.reserve(n, 2 * n);
  m.set_vertex_count(n);
  const std::size_t reserved = m.memory_bytes();
  grow_at_random(m, n, 7);
  // n finite vertices plus I: 2(n+1) - 4 faces, 3(n+1) - 6 edges.
  EXPECT_EQ(m.face_count(), 2 * n - 2);
  EXPECT_EQ(m.edge_count(), 3 * n - 3);
  EXPECT_EQ(m.memory_bytes(), reserved);  // no reallocation while growing into the reserve
  const double per_vertex = static_cast<double>(m.memory_bytes()) / n;
  EXPECT_LE(per_vertex, 90.0);
  ASSERT_VALID(m);
  RecordProperty("dcel_bytes_per_vertex", std::to_string(per_vertex));
}

}  // namespace
}  // namespace meshstep
