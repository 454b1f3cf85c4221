#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "report.h"

namespace bearing::verify {

namespace fs = std::filesystem;

namespace {

const char* panel_name(Panel p) {
  switch (p) {
    case Panel::spectrum:
      return "spectrum";
    case Panel::trace:
      return "trace";
    case Panel::force_approach:
      return "force_approach";
    case Panel::series:
      break;
  }
  return "series";
}

nlohmann::json figure_json(const Figure& f) {
  nlohmann::json series = nlohmann::json::array();
  for (const auto& s : f.series)
    series.push_back({{"label", s.label}, {"x", s.x}, {"y", s.y}, {"style", s.style}});
  nlohmann::json markers = nlohmann::json::array();
  for (const auto& m : f.markers) markers.push_back({{"x", m.x}, {"label", m.label}});
  nlohmann::json laws = nlohmann::json::array();
  for (const auto& l : f.laws)
    laws.push_back({{"label", l.label}, {"K", l.K}, {"exponent", l.exponent}});
  return {{"name", f.name},       {"title", f.title},   {"x_label", f.x_label},
          {"y_label", f.y_label}, {"log_x", f.log_x},   {"log_y", f.log_y},
          {"series", series},     {"markers", markers}, {"panel", panel_name(f.panel)},
          {"laws", laws}};
}

}  // namespace

void write_figures(const Report& report, const std::string& dir, const std::string& plot_script) {
  std::vector<Figure> figures;
  for (const auto& r : report.results)
    figures.insert(figures.end(), r.figures.begin(), r.figures.end());
  draw_figures(figures, dir, plot_script);
}

void draw_figures(const std::vector<Figure>& figures, const std::string& dir,
                  const std::string& plot_script) {
  nlohmann::json all = nlohmann::json::array();
  for (const auto& f : figures) all.push_back(figure_json(f));
  const fs::path data = fs::path(dir) / "figures.json";
  fs::remove(fs::path(dir) / "NO_FIGURES.txt");
  std::ofstream(data) << all.dump() << "\n";
  for (const auto& f : all) fs::remove(fs::path(dir) / (f["name"].get<std::string>() + ".png"));
  if (all.empty()) return;
  // Debian's matplotlib is /usr/bin/python3's (the python3 on PATH may be another interpreter).
  const std::string command = "/usr/bin/python3 '" + plot_script + "' '" + data.string() + "' '" +
                              dir + "' > '" + dir + "/plot.log' 2>&1";
  if (std::system(command.c_str()) != 0)
    std::ofstream(fs::path(dir) / "NO_FIGURES.txt")
        << "The figures were not drawn: /usr/bin/python3 with matplotlib is needed "
           "(Debian: python3-matplotlib); see plot.log. Their data is in figures.json.\n";
}

}  // namespace bearing::verify
