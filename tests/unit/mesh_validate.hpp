// Connectivity checks written against the TriangleMesh concept only, so the same checks
// judge every data structure, and a canonical face set to compare structures by.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "meshstep/mesh/concept.hpp"

namespace meshstep {

// Every problem found, one line each; empty when the connectivity is consistent.
// Handles are only dereferenced once they are known to belong to a live face, so a corrupt
// structure produces messages rather than out-of-bounds reads.
// check_vertex_half_edges = false skips the one relation the concept lets remove_face
// leave stale until rebuild_vertex_half_edges.
template <TriangleMesh M>
std::vector<std::string> validate_connectivity(const M& m, bool check_vertex_half_edges = true) {
  std::vector<std::string> problems;
  auto name = [](std::uint32_t x) {
    if (x == kNone) return std::string("none");
    if (x == kInfiniteVertex) return std::string("inf");
    return std::to_string(x);
  };
  // Messages are only built when something is wrong: this runs after every mutation of
  // long random tests, where formatting context up front would dominate.
  auto face_problem = [&](FaceId f, const std::string& what) {
    problems.push_back("face " + std::to_string(f) + ": " + what);
  };
  auto edge_problem = [&](FaceId f, HalfEdge h, const std::string& what) {
    problems.push_back("face " + std::to_string(f) + ", half-edge " + name(h) + " (" +
                       name(m.origin(h)) + "->" + name(m.dest(h)) + "): " + what);
  };

  // Pass 1: the half-edges of live faces, found by walking next from half_edge(f).
  // Sorted vectors rather than hash sets: this is the bulk of the random tests' time.
  std::vector<HalfEdge> live;
  live.reserve(3 * m.face_count());
  std::size_t live_faces = 0;
  bool faces_ok = true;
  for (FaceId f = 0; f < m.face_capacity(); ++f) {
    if (!m.is_live(f)) continue;
    ++live_faces;
    const HalfEdge h0 = m.half_edge(f);
    if (h0 == kNone) {
      face_problem(f, "half_edge is none");
      faces_ok = false;
      continue;
    }
    if (m.face(h0) != f) {
      face_problem(f, "face(half_edge(f)) is " + name(m.face(h0)));
      faces_ok = false;
      continue;
    }
    const HalfEdge h1 = m.next(h0);
    if (h1 == kNone || m.face(h1) != f) {
      face_problem(f, "next leaves the face");
      faces_ok = false;
      continue;
    }
    const HalfEdge h2 = m.next(h1);
    if (h2 == kNone || m.face(h2) != f) {
      face_problem(f, "next(next) leaves the face");
      faces_ok = false;
      continue;
    }
    if (m.next(h2) != h0 || h0 == h1 || h1 == h2 || h0 == h2) {
      face_problem(f, "next^3 is not the identity on three distinct half-edges");
      faces_ok = false;
      continue;
    }
    const std::array<HalfEdge, 3> corners{h0, h1, h2};
    for (std::uint32_t i = 0; i < 3; ++i) {
      if (m.corner(corners[i]) != i)
        edge_problem(f, corners[i], "corner() is " + std::to_string(m.corner(corners[i])) + ", not " + std::to_string(i));
      if (((m.constraint_mask(f) >> i) & 1u) != std::uint32_t{m.is_constrained(corners[i])})
        edge_problem(f, corners[i], "constraint_mask() disagrees with is_constrained()");
    }
    live.insert(live.end(), corners.begin(), corners.end());
  }
  std::sort(live.begin(), live.end());
  for (std::size_t i = 1; i < live.size(); ++i) {
    if (live[i] == live[i - 1]) {
      problems.push_back("half-edge " + name(live[i]) + " belongs to two faces");
      faces_ok = false;
    }
  }
  auto is_live_half_edge = [&](HalfEdge h) {
    return std::binary_search(live.begin(), live.end(), h);
  };
  if (live_faces != m.face_count())
    problems.push_back("face_count() is " + std::to_string(m.face_count()) + " but " +
                       std::to_string(live_faces) + " faces are live");
  // The remaining checks follow next/twin freely, which is only safe on sound faces.
  if (!faces_ok) return problems;

  // Pass 2: per half-edge relations.
  struct Directed {
    VertexId from, to;
    FaceId face;
    bool operator<(const Directed& o) const {
      return from != o.from ? from < o.from : to != o.to ? to < o.to : face < o.face;
    }
  };
  std::vector<Directed> directed;  // each directed edge must appear once
  directed.reserve(live.size());
  std::vector<VertexId> vertices;
  vertices.reserve(live.size());
  for (FaceId f = 0; f < m.face_capacity(); ++f) {
    if (!m.is_live(f)) continue;
    const HalfEdge h0 = m.half_edge(f);
    const HalfEdge hs[3] = {h0, m.next(h0), m.next(m.next(h0))};
    const VertexId vs[3] = {m.origin(hs[0]), m.origin(hs[1]), m.origin(hs[2])};
    if (vs[0] == vs[1] || vs[1] == vs[2] || vs[0] == vs[2])
      face_problem(f, "repeated vertex (" + name(vs[0]) + "," + name(vs[1]) + "," +
                          name(vs[2]) + ")");
    for (int i = 0; i < 3; ++i) {
      const HalfEdge h = hs[i];
      vertices.push_back(vs[i]);
      directed.push_back({vs[i], vs[(i + 1) % 3], f});
      if (m.prev(h) != hs[(i + 2) % 3]) edge_problem(f, h, "prev is not next^2");
      if (m.dest(h) != vs[(i + 1) % 3]) edge_problem(f, h, "dest is not origin(next)");
      if (m.apex(h) != vs[(i + 2) % 3]) edge_problem(f, h, "apex is not origin(prev)");
      const HalfEdge t = m.twin(h);
      if (t == kNone) continue;
      if (!is_live_half_edge(t)) {
        edge_problem(f, h, "twin " + name(t) + " is not a half-edge of a live face");
        continue;
      }
      if (m.face(t) == f) edge_problem(f, h, "twin lies in the same face");
      if (m.twin(t) != h) edge_problem(f, h, "twin(twin(h)) is " + name(m.twin(t)));
      if (m.origin(t) != m.dest(h) || m.dest(t) != m.origin(h))
        edge_problem(f, h, "twin runs " + name(m.origin(t)) + "->" + name(m.dest(t)));
      if (m.is_constrained(t) != m.is_constrained(h))
        edge_problem(f, h, "constraint flag differs from its twin's");
    }
  }
  // Two faces with the same directed edge would make the surface non-manifold there
  // (and twin() could only name one of them).
  std::sort(directed.begin(), directed.end());
  for (std::size_t i = 1; i < directed.size(); ++i)
    if (directed[i].from == directed[i - 1].from && directed[i].to == directed[i - 1].to)
      problems.push_back("directed edge " + name(directed[i].from) + "->" +
                         name(directed[i].to) + " appears in faces " +
                         std::to_string(directed[i - 1].face) + " and " +
                         std::to_string(directed[i].face));

  // Pass 3: every vertex of a live face knows a live half-edge leaving it.
  if (!check_vertex_half_edges) return problems;
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  for (const VertexId v : vertices) {
    const HalfEdge h = m.vertex_half_edge(v);
    if (!is_live_half_edge(h))
      problems.push_back("vertex " + name(v) + ": vertex_half_edge " + name(h) +
                         " is not live");
    else if (m.origin(h) != v)
      problems.push_back("vertex " + name(v) + ": vertex_half_edge leaves " +
                         name(m.origin(h)));
  }
  return problems;
}

// Each live face as its three vertex ids, rotated (orientation kept) so the smallest id
// comes first; sorted. Two structures holding the same triangulation give equal sets
// whatever their handles.
template <TriangleMesh M>
std::vector<std::array<std::uint32_t, 3>> face_set(const M& m) {
  std::vector<std::array<std::uint32_t, 3>> out;
  out.reserve(m.face_count());
  for (FaceId f = 0; f < m.face_capacity(); ++f) {
    if (!m.is_live(f)) continue;
    const HalfEdge h = m.half_edge(f);
    std::array<std::uint32_t, 3> t = {m.origin(h), m.dest(h), m.apex(h)};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    out.push_back(t);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace meshstep
