// Plain 3D point: the vertex type of triangle surfaces (io/surface_io.hpp).
#pragma once

namespace meshstep {

struct Point3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
  friend bool operator==(const Point3&, const Point3&) = default;
};

}  // namespace meshstep
