// A bounding-box tree (kd-split at the median of box centers) over vertices or triangles,
// for finding the items a triangle or a segment may touch.
//
// Chosen over a uniform grid because meshes are rarely uniform: a graded mesh packs most
// vertices into a few grid cells, and a fan of long thin triangles (a circle and its
// center) crosses a large share of all cells per triangle; either turns a grid quadratic.
// Node boxes are unions of item boxes, so their corners are input coordinates and callers
// can prune with exact predicates.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "meshstep/geometry/point.hpp"

namespace meshstep::check_detail {

class BoxTree {
 public:
  // box_of(id) gives the box of each item (finite coordinates); it is called only here.
  template <class BoxOf>
  BoxTree(const std::vector<std::uint32_t>& items, BoxOf&& box_of) {
    if (items.empty()) return;
    std::vector<Item> work;
    work.reserve(items.size());
    for (std::uint32_t id : items) work.push_back({box_of(id), id});
    nodes_.reserve(2 * (items.size() / kLeafSize + 1));
    build(work, 0, static_cast<std::uint32_t>(work.size()));
    order_.reserve(work.size());
    for (const Item& item : work) order_.push_back(item.id);
  }

  // Calls visit(id) for every item of every leaf reached, descending into a node only
  // when skip(node_box) is false. A superset of the items that matter: callers decide.
  template <class Skip, class Visit>
  void query(Skip&& skip, Visit&& visit) const {
    if (nodes_.empty()) return;
    std::uint32_t stack[kMaxDepth];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const std::uint32_t id = stack[--top];
      const Node& node = nodes_[id];
      if (skip(node.box)) continue;
      if (node.right == 0) {
        for (std::uint32_t k = node.begin; k < node.end; ++k) visit(order_[k]);
        continue;
      }
      stack[top++] = node.right;
      stack[top++] = id + 1;  // the left child follows its parent
    }
  }

 private:
  static constexpr std::uint32_t kLeafSize = 16;
  static constexpr int kMaxDepth = 128;  // median splits: depth <= log2(n) + 1
  struct Item {
    BBox box;
    std::uint32_t id;
  };
  struct Node {
    BBox box;                  // union of the boxes below
    std::uint32_t begin, end;  // range of order_
    std::uint32_t right;       // right child; the left child is the next node; 0: a leaf
  };

  void build(std::vector<Item>& work, std::uint32_t begin, std::uint32_t end) {
    const auto id = static_cast<std::uint32_t>(nodes_.size());
    BBox box;
    for (std::uint32_t k = begin; k < end; ++k) {
      box.add(work[k].box.lo);
      box.add(work[k].box.hi);
    }
    nodes_.push_back({box, begin, end, 0});
    if (end - begin <= kLeafSize) return;
    // Median split of the centers across the longer side (halved to avoid overflow).
    const bool by_x = box.hi.x * 0.5 - box.lo.x * 0.5 >= box.hi.y * 0.5 - box.lo.y * 0.5;
    auto center = [by_x](const Item& item) {
      return by_x ? item.box.lo.x * 0.5 + item.box.hi.x * 0.5
                  : item.box.lo.y * 0.5 + item.box.hi.y * 0.5;
    };
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(work.begin() + begin, work.begin() + mid, work.begin() + end,
                     [&](const Item& a, const Item& b) { return center(a) < center(b); });
    build(work, begin, mid);
    const auto right = static_cast<std::uint32_t>(nodes_.size());
    build(work, mid, end);
    nodes_[id].right = right;
  }

  std::vector<std::uint32_t> order_;
  std::vector<Node> nodes_;
};

// Cheap box tests shared by the users of the tree.
inline bool boxes_overlap(const BBox& a, const BBox& b) {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y;
}
inline bool box_contains(const BBox& box, const Point& p) {
  return p.x >= box.lo.x && p.x <= box.hi.x && p.y >= box.lo.y && p.y <= box.hi.y;
}

// True when the box lies strictly on the right of the directed line pq: no point of it is
// on or left of the line. Exact when the box corners are input coordinates.
bool box_right_of(const BBox& box, const Point& p, const Point& q);

}  // namespace meshstep::check_detail
