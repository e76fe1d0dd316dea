#include "check/problem_log.hpp"

#include <cstdio>

namespace meshstep::check_detail {

std::string coordinate(double value) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

std::string point_text(double x, double y) {
  // Appending rather than chaining operator+ also dodges a GCC 12 -Wrestrict false alarm.
  std::string text = "(";
  text += coordinate(x);
  text += ", ";
  text += coordinate(y);
  text += ")";
  return text;
}

}  // namespace meshstep::check_detail
