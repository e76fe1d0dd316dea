// The events of one log block, decoded: fixed-size heads plus pools for their variable
// parts, so a block of tens of thousands of events is a handful of allocations.
#pragma once

#include <cstdint>
#include <vector>

#include "meshstep/replay/event.hpp"

namespace meshstep::replay {

struct EventHead {
  EventType type;
  std::uint8_t code;
  std::array<std::uint32_t, 4> ids;
  Point point;
  double value;
  // Ends of this event's parts in the pools; each begins where the previous event's ends.
  std::uint32_t list_end, points_end, writes_end;
};

class DecodedEvents {
 public:
  std::size_t size() const { return heads.size(); }
  Event operator[](std::size_t i) const {
    const EventHead& h = heads[i];
    const EventHead* before = i ? &heads[i - 1] : nullptr;
    const std::uint32_t l0 = before ? before->list_end : 0, p0 = before ? before->points_end : 0,
                        w0 = before ? before->writes_end : 0;
    Event e;
    e.type = h.type;
    e.code = h.code;
    e.ids = h.ids;
    e.point = h.point;
    e.value = h.value;
    e.list = {lists.data() + l0, h.list_end - l0};
    e.points = {points.data() + p0, h.points_end - p0};
    e.writes = {writes.data() + w0, h.writes_end - w0};
    return e;
  }
  std::span<const SlotWrite> writes_of(std::size_t i) const {
    const std::uint32_t w0 = i ? heads[i - 1].writes_end : 0;
    return {writes.data() + w0, heads[i].writes_end - w0};
  }
  void clear() {
    heads.clear();
    lists.clear();
    points.clear();
    writes.clear();
  }

  std::vector<EventHead> heads;
  std::vector<std::uint32_t> lists;
  std::vector<Point> points;
  std::vector<SlotWrite> writes;
};

}  // namespace meshstep::replay
