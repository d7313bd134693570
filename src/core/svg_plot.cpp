#include "core/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pt {
namespace {

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

std::string escape(const std::string& s) {
  std::string o;
  for (char c : s) o += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
  return o;
}

}  // namespace

std::string svg_loglog_plot(const std::vector<PlotSeries>& series, const std::string& title, const std::string& x_label,
                            const std::string& y_label) {
  const double W = 760, H = 480, L = 80, R = 200, T = 40, B = 60;
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const PlotSeries& s : series)
    for (size_t i = 0; i < s.x.size(); ++i)
      if (s.x[i] > 0 && s.y[i] > 0) {
        x0 = std::min(x0, std::log10(s.x[i]));
        x1 = std::max(x1, std::log10(s.x[i]));
        y0 = std::min(y0, std::log10(s.y[i]));
        y1 = std::max(y1, std::log10(s.y[i]));
      }
  if (!(x1 >= x0)) x0 = 0, x1 = 1;
  if (!(y1 >= y0)) y0 = 0, y1 = 1;
  x0 = std::floor(x0), x1 = std::max(std::ceil(x1), x0 + 1), y0 = std::floor(y0), y1 = std::max(std::ceil(y1), y0 + 1);
  auto px = [&](double v) { return L + (std::log10(v) - x0) / (x1 - x0) * (W - L - R); };
  auto py = [&](double v) { return H - B - (std::log10(v) - y0) / (y1 - y0) * (H - T - B); };
  std::string s = "<svg xmlns='http://www.w3.org/2000/svg' width='" + fmt("%.0f", W) + "' height='" + fmt("%.0f", H) +
                  "' font-family='sans-serif' font-size='12'>\n<rect width='100%' height='100%' fill='white'/>\n";
  s += "<text x='" + fmt("%.0f", L) + "' y='24' font-size='15'>" + escape(title) + "</text>\n";
  for (double e = x0; e <= x1 + 1e-9; e += 1) {
    const double X = L + (e - x0) / (x1 - x0) * (W - L - R);
    s += "<line x1='" + fmt("%.1f", X) + "' y1='" + fmt("%.0f", T) + "' x2='" + fmt("%.1f", X) + "' y2='" + fmt("%.0f", H - B) +
         "' stroke='#ddd'/><text x='" + fmt("%.1f", X) + "' y='" + fmt("%.0f", H - B + 16) + "' text-anchor='middle'>1e" +
         fmt("%.0f", e) + "</text>\n";
  }
  for (double e = y0; e <= y1 + 1e-9; e += 1) {
    const double Y = H - B - (e - y0) / (y1 - y0) * (H - T - B);
    s += "<line x1='" + fmt("%.0f", L) + "' y1='" + fmt("%.1f", Y) + "' x2='" + fmt("%.0f", W - R) + "' y2='" + fmt("%.1f", Y) +
         "' stroke='#ddd'/><text x='" + fmt("%.0f", L - 6) + "' y='" + fmt("%.1f", Y + 4) + "' text-anchor='end'>1e" +
         fmt("%.0f", e) + "</text>\n";
  }
  s += "<text x='" + fmt("%.0f", (L + W - R) / 2) + "' y='" + fmt("%.0f", H - 18) + "' text-anchor='middle'>" + escape(x_label) +
       "</text>\n<text transform='translate(18," + fmt("%.0f", (T + H - B) / 2) + ") rotate(-90)' text-anchor='middle'>" +
       escape(y_label) + "</text>\n";
  static const char* kColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf"};
  for (size_t k = 0; k < series.size(); ++k) {
    const char* col = kColors[k % 8];
    std::string pts;
    for (size_t i = 0; i < series[k].x.size(); ++i)
      if (series[k].x[i] > 0 && series[k].y[i] > 0)
        pts += fmt("%.1f", px(series[k].x[i])) + "," + fmt("%.1f", py(series[k].y[i])) + " ";
    s += "<polyline fill='none' stroke='" + std::string(col) + "' stroke-width='2' points='" + pts + "'/>\n";
    const double ly = T + 10 + 18.0 * double(k);
    s += "<line x1='" + fmt("%.0f", W - R + 10) + "' y1='" + fmt("%.0f", ly) + "' x2='" + fmt("%.0f", W - R + 30) + "' y2='" +
         fmt("%.0f", ly) + "' stroke='" + col + "' stroke-width='2'/><text x='" + fmt("%.0f", W - R + 34) + "' y='" +
         fmt("%.0f", ly + 4) + "'>" + escape(series[k].label) + "</text>\n";
  }
  return s + "</svg>\n";
}

}  // namespace pt
