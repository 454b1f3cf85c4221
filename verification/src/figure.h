#pragma once
// A figure a check hands to the report: data only. The report writes every figure's data to
// figures/figures.json and plot_figures.py draws them with bearing.plot's panels (the functions
// bearing-plot draws with; python/bearing/plot/report_figures.py) and Debian's matplotlib.

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

/// A power law Q = K δ^n drawn as a line by the force_approach panel.
struct PowerLaw {
  std::string label;
  double K = 0.0;         ///< [N/m^n]
  double exponent = 1.5;  ///< n [-]
};

/// The bearing.plot panel that draws a figure (report_figures.py): series (lines and points, the
/// markers as labelled vertical lines); spectrum (amplitude spectra, spectrum_axes: x frequency
/// [Hz], the markers the expected lines); trace (time traces, trace_axes: x time [s]);
/// force_approach (force_approach_axes: series[0] the points, approach [m] and force [N];
/// laws[0] drawn solid, laws[1] dashed).
enum class Panel { series, spectrum, trace, force_approach };

struct Figure {
  std::string name;  ///< file stem, unique in a report: letters, digits, '-', '_'
  std::string title;
  std::string x_label;  ///< with unit, e.g. "load Q [N]"
  std::string y_label;
  bool log_x = false;
  bool log_y = false;
  std::vector<Series> series;
  std::vector<Marker> markers;
  Panel panel = Panel::series;
  std::vector<PowerLaw> laws;  ///< force_approach only
};

}  // namespace bearing::verify
