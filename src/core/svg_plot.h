// A minimal log-log line plot written as SVG, for the speed-against-error curves.
#pragma once
#include <string>
#include <vector>

namespace pt {

struct PlotSeries {
  std::string label;
  std::vector<double> x, y;  // positive values (log axes)
};

std::string svg_loglog_plot(const std::vector<PlotSeries>& series, const std::string& title, const std::string& x_label,
                            const std::string& y_label);

}  // namespace pt
