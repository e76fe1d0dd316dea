// Collects the problems found by the check stages, and names things the way the files do.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "meshstep/check/mesh_check.hpp"

namespace meshstep::check_detail {

class ProblemLog {
 public:
  explicit ProblemLog(std::size_t max_problems) : max_(max_problems) {}

  // Takes a callable that builds the text, and calls it only when the text is kept: a badly
  // broken million-triangle mesh can have millions of problems, and formatting them all
  // would cost more than finding them.
  template <class Describe>
  void add(Describe&& describe) {
    ++count_;
    if (problems_.size() < max_) problems_.push_back(std::forward<Describe>(describe)());
  }

  std::size_t count() const { return count_; }

  CheckReport take() && {
    CheckReport report;
    report.ok = count_ == 0;
    report.problems = std::move(problems_);
    report.problem_count = count_;
    return report;
  }

 private:
  std::size_t max_;
  std::size_t count_ = 0;
  std::vector<std::string> problems_;
};

// A 0-based index as the user's files number it.
inline std::string number(std::size_t index, int first_index) {
  return std::to_string(static_cast<long long>(index) + first_index);
}

// Shortest text that reads back to the same double, so "moved" vertices show the change.
std::string coordinate(double value);
std::string point_text(double x, double y);

}  // namespace meshstep::check_detail
