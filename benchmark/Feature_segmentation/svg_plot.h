// SPDX-License-Identifier: GPL-3.0-or-later
// A small SVG line plot for the benchmark programs: panels of series against one x axis
// (linear or logarithmic y axis, ticks, labels, a legend on the right), stacked into one
// document with a caption (svg_figure()), or written one by one (svg_panel()).
#ifndef FS_BENCH_SVG_PLOT_H
#define FS_BENCH_SVG_PLOT_H

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

namespace fs_bench {

// One number through a printf format.
inline std::string format(const char* f, double x)
{
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), f, x);
  return buffer;
}

// A curve of a panel: its legend, stroke colour, dash pattern ("" for solid) and values.
struct Series
{
  std::string name, colour, dash;
  std::vector<double> y;
};

// Tick positions of a linear axis over [lo, hi]: steps of 1, 2 or 5 times a power of 10,
// about six of them.
inline std::vector<double> linear_ticks(double lo, double hi)
{
  const double raw = (hi - lo) / 6;
  const double p = std::pow(10., std::floor(std::log10(raw)));
  double step = p;
  for(double m : {1., 2., 5., 10.})
    if(m * p >= raw) { step = m * p; break; }
  std::vector<double> t;
  for(double x = std::ceil(lo / step) * step; x <= hi + 1e-9 * step; x += step)
    t.push_back(std::abs(x) < 1e-12 * step ? 0. : x);
  return t;
}

inline std::string xml_text(const std::string& s)
{
  std::string out;
  for(char c : s)
  {
    if(c == '<') out += "&lt;";
    else if(c == '>') out += "&gt;";
    else if(c == '&') out += "&amp;";
    else out += c;
  }
  return out;
}

// One panel, 470 x 300 at 90 from the left and `top` from the top: the series against
// `x` (ticks at the x values, "%.1f"), with axes, ticks, labels and a legend on the
// right. A log y-axis, if `allow_log`, when the values span more than a factor 20 (so that
// milliseconds stay readable next to seconds).
inline void svg_panel(std::ostream& out, double top, const std::string& title, const std::string& x_label,
                      const std::string& y_label, const std::vector<double>& x,
                      const std::vector<Series>& series, bool allow_log)
{
  const double left = 90, width = 470, height = 300, legend_x = left + width + 20;
  double lo = 1e300, hi = -1e300;
  for(const Series& s : series)
    for(double v : s.y) { lo = (std::min)(lo, v); hi = (std::max)(hi, v); }
  const bool log_axis = allow_log && lo > 0 && hi / lo > 20;
  std::vector<double> ticks;
  std::vector<double> minor;
  if(log_axis)
  {
    lo = std::pow(10., std::floor(std::log10(lo)));
    hi = std::pow(10., std::ceil(std::log10(hi)));
    for(double d = lo; d < hi * 1.001; d *= 10)
    {
      ticks.push_back(d);
      for(int m = 2; m <= 9 && d * m < hi; ++m) minor.push_back(d * m);
    }
  }
  else
  {
    const double pad = (hi > lo) ? 0.05 * (hi - lo) : (std::max)(1., std::abs(hi)) * 0.05;
    lo -= pad;
    hi += pad;
    ticks = linear_ticks(lo, hi);
  }
  const double x_lo = x.front() - 0.05, x_hi = x.back() + 0.05;
  auto px = [&](double a) { return left + (a - x_lo) / (x_hi - x_lo) * width; };
  auto py = [&](double v) {
    const double t = log_axis ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo))
                              : (v - lo) / (hi - lo);
    return top + height - t * height;
  };

  out << "<text x=\"" << left + width / 2 << "\" y=\"" << top - 12
      << "\" text-anchor=\"middle\" font-size=\"15\" font-weight=\"bold\">" << xml_text(title) << "</text>\n";
  out << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << width << "\" height=\"" << height
      << "\" fill=\"none\" stroke=\"black\"/>\n";
  for(double v : minor)
    out << "<line x1=\"" << left << "\" y1=\"" << py(v) << "\" x2=\"" << left + 4 << "\" y2=\"" << py(v)
        << "\" stroke=\"black\"/>\n";
  for(double v : ticks)
  {
    out << "<line x1=\"" << left << "\" y1=\"" << py(v) << "\" x2=\"" << left + width << "\" y2=\"" << py(v)
        << "\" stroke=\"#dddddd\"/>\n";
    out << "<line x1=\"" << left - 6 << "\" y1=\"" << py(v) << "\" x2=\"" << left << "\" y2=\"" << py(v)
        << "\" stroke=\"black\"/>\n";
    out << "<text x=\"" << left - 9 << "\" y=\"" << py(v) + 4 << "\" text-anchor=\"end\" font-size=\"12\">"
        << format("%g", v) << "</text>\n";
  }
  for(double a : x)
  {
    out << "<line x1=\"" << px(a) << "\" y1=\"" << top + height << "\" x2=\"" << px(a) << "\" y2=\""
        << top + height + 6 << "\" stroke=\"black\"/>\n";
    out << "<text x=\"" << px(a) << "\" y=\"" << top + height + 20 << "\" text-anchor=\"middle\" font-size=\"12\">"
        << format("%.1f", a) << "</text>\n";
  }
  out << "<text x=\"" << left + width / 2 << "\" y=\"" << top + height + 40
      << "\" text-anchor=\"middle\" font-size=\"13\">" << xml_text(x_label) << "</text>\n";
  out << "<text transform=\"translate(" << left - 62 << ',' << top + height / 2
      << ") rotate(-90)\" text-anchor=\"middle\" font-size=\"13\">" << xml_text(y_label)
      << (log_axis ? " (log scale)" : "") << "</text>\n";

  for(std::size_t k = 0; k < series.size(); ++k)
  {
    const Series& s = series[k];
    out << "<polyline fill=\"none\" stroke=\"" << s.colour << "\" stroke-width=\"2\"";
    if(!s.dash.empty()) out << " stroke-dasharray=\"" << s.dash << "\"";
    out << " points=\"";
    for(std::size_t i = 0; i < x.size(); ++i) out << px(x[i]) << ',' << py(s.y[i]) << ' ';
    out << "\"/>\n";
    for(std::size_t i = 0; i < x.size(); ++i)
      out << "<circle cx=\"" << px(x[i]) << "\" cy=\"" << py(s.y[i]) << "\" r=\"2.5\" fill=\"" << s.colour
          << "\"/>\n";
    const double ly = top + 20 + 22 * double(k);
    out << "<line x1=\"" << legend_x << "\" y1=\"" << ly << "\" x2=\"" << legend_x + 26 << "\" y2=\"" << ly
        << "\" stroke=\"" << s.colour << "\" stroke-width=\"2\"";
    if(!s.dash.empty()) out << " stroke-dasharray=\"" << s.dash << "\"";
    out << "/>\n<text x=\"" << legend_x + 32 << "\" y=\"" << ly + 4 << "\" font-size=\"12\">" << xml_text(s.name)
        << "</text>\n";
  }
}

// A panel of svg_figure(): the arguments of svg_panel() but the stream, position and x.
struct Panel
{
  std::string title, x_label, y_label;
  std::vector<Series> series;
  bool allow_log = false;
};

// A whole SVG document, 860 wide on a white background: the panels stacked from the top,
// 400 apart, against the same `x`, and `caption` in small print at the bottom.
inline void svg_figure(std::ostream& out, const std::vector<double>& x, const std::vector<Panel>& panels,
                       const std::string& caption)
{
  const int width = 860, height = 40 + 400 * int(panels.size());
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << ' ' << height << "\" font-family=\"DejaVu Sans, Arial, sans-serif\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for(std::size_t k = 0; k < panels.size(); ++k)
  {
    const Panel& p = panels[k];
    svg_panel(out, 50 + 400 * double(k), p.title, p.x_label, p.y_label, x, p.series, p.allow_log);
  }
  out << "<text x=\"20\" y=\"" << height - 15 << "\" font-size=\"11\" fill=\"#444444\">" << xml_text(caption)
      << "</text>\n</svg>\n";
}

} // namespace fs_bench

#endif // FS_BENCH_SVG_PLOT_H
