// SPDX-License-Identifier: GPL-3.0-or-later
// Small pieces of the evaluation's reports: numbers as text, comma-separated lists on the
// command line, and a table of text cells written as markdown (to read, and to print) and
// as CSV (for scripts).

#ifndef CGAL_FEATURE_SEGMENTATION_BENCHMARK_REPORT_H
#define CGAL_FEATURE_SEGMENTATION_BENCHMARK_REPORT_H

#include <cstddef>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace fs_evaluation {

/// `v` with `digits` digits after the point: "0.938".
inline std::string fmt(double v, int digits = 3)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

/// `v` as a stream writes it by default (six significant digits): "0.001", "40".
inline std::string plain(double v)
{
  std::ostringstream s;
  s << v;
  return s.str();
}

/// The items of "a,b,c" (an empty item is kept, so that "0,,1" can be refused).
inline std::vector<std::string> split_commas(const std::string& list)
{
  std::vector<std::string> items;
  std::stringstream ss(list);
  std::string item;
  while(std::getline(ss, item, ',')) items.push_back(item);
  return items;
}

/// A table of text cells: a header and rows of as many cells.
struct Text_table
{
  std::vector<std::string> header;
  std::vector<std::vector<std::string> > rows;

  void write_markdown(std::ostream& os) const
  {
    const auto line = [&os](const std::vector<std::string>& cells) {
      os << "|";
      for(const std::string& c : cells) os << " " << c << " |";
      os << "\n";
    };
    line(header);
    os << "|";
    for(std::size_t i = 0; i < header.size(); ++i) os << "---|";
    os << "\n";
    for(const auto& r : rows) line(r);
  }

  /// Cells holding a comma or a quote are quoted (a quote doubled), as RFC 4180 says.
  void write_csv(std::ostream& os) const
  {
    const auto line = [&os](const std::vector<std::string>& cells) {
      for(std::size_t i = 0; i < cells.size(); ++i)
      {
        const std::string& c = cells[i];
        if(i > 0) os << ",";
        if(c.find_first_of(",\"") == std::string::npos) { os << c; continue; }
        os << '"';
        for(char ch : c) os << (ch == '"' ? "\"\"" : std::string(1, ch));
        os << '"';
      }
      os << "\n";
    };
    line(header);
    for(const auto& r : rows) line(r);
  }
};

} // namespace fs_evaluation

#endif // CGAL_FEATURE_SEGMENTATION_BENCHMARK_REPORT_H
