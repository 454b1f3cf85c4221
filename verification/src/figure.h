#pragma once
// A figure a check hands to the report: data only. The report writes every figure's data to
// figures/figures.json and plot_figures.py draws them with Debian's matplotlib.

#include <string>
#include <vector>

namespace bearing::verify {

struct Series {
  std::string label;
  std::vector<double> x;
  std::vector<double> y;
  std::string style = "line";  ///< "line", "marker" or "line+marker"
};

/// A labelled vertical line (a spectral line's expected frequency, a tolerance …).
struct Marker {
  double x = 0.0;
  std::string label;
};

struct Figure {
  std::string name;  ///< file stem, unique in a report: letters, digits, '-', '_'
  std::string title;
  std::string x_label;  ///< with unit, e.g. "load Q [N]"
  std::string y_label;
  bool log_x = false;
  bool log_y = false;
  std::vector<Series> series;
  std::vector<Marker> markers;
};

}  // namespace bearing::verify
