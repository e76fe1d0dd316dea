// A table of text cells for `meshstep compare`: printed with aligned columns (numbers to the
// right, words to the left) or as CSV (RFC 4180 quoting).
#pragma once

#include <string>
#include <vector>

namespace meshstep::app {

class TextTable {
 public:
  explicit TextTable(std::vector<std::string> header) : header_(std::move(header)) {}
  // A row of as many cells as the header has (missing cells are empty).
  void add_row(std::vector<std::string> cells);
  // Columns two spaces apart, each as wide as its widest cell; a column whose cells are all
  // numbers (or empty, or "-") is right-aligned. A rule of dashes under the header.
  std::string text() const;
  std::string csv() const;

 private:
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

// "30.02": a number as a table shows it, `digits` after the point; "-" for NaN.
std::string fixed(double value, int digits);

}  // namespace meshstep::app
