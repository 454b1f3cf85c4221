#include "calibration_report.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "bearing/hertz.h"
#include "html.h"
#include "report.h"
#include "run_info.h"

namespace bearing::verify {

namespace fs = std::filesystem;

namespace {

struct Law {
  std::string name;
  double K;         ///< [N/m^n]
  double exponent;  ///< n
  double approach(double q) const { return std::pow(q / K, 1.0 / exponent); }
};

// The calibrated law and the three Hertz methods of one race.
std::vector<Law> laws(const CalibrationStudy& s, Race race) {
  const RaceLaw& cal = race == Race::inner ? s.calibration.inner : s.calibration.outer;
  std::vector<Law> out = {{"calibrated (FE " + s.geometry + ")", cal.K, cal.exponent}};
  for (HertzMethod m :
       {HertzMethod::exact, HertzMethod::hamrock_brewe, HertzMethod::harris_table}) {
    const RaceContact rc = race_contact(s.bearing, race, *make_hertz_solution(m));
    out.push_back({name_of(kContactLaws, contact_law(m)), rc.K, rc.exponent});
  }
  return out;
}

// Q geometric from the calibrated range's ends, `n` points.
std::vector<double> loads(const ContactCalibration& c, int n) {
  std::vector<double> q;
  const double lo = c.load_min > 0 ? c.load_min : c.load_max / 10;
  for (int k = 0; k < n; ++k) q.push_back(lo * std::pow(c.load_max / lo, k / double(n - 1)));
  return q;
}

// The FE curve's approach at load q (log–log interpolation; NaN more than 2 % outside the
// curve: its first step lands near, not exactly on, the lightest load asked for).
double fe_approach(const FeCurve& c, double q) {
  for (std::size_t i = 1; i < c.force.size(); ++i) {
    const double lo = i == 1 ? 0.98 : 1 - 1e-9, hi = i + 1 == c.force.size() ? 1.02 : 1 + 1e-9;
    if (q < c.force[i - 1] * lo || q > c.force[i] * hi) continue;
    const double t = std::log(q / c.force[i - 1]) / std::log(c.force[i] / c.force[i - 1]);
    return c.approach[i - 1] * std::pow(c.approach[i] / c.approach[i - 1], t);
  }
  return NAN;
}

std::string fmt(const char* f, double x) {
  if (!std::isfinite(x)) return "—";
  char b[48];
  std::snprintf(b, sizeof b, f, x);
  return b;
}

Figure law_figure(const CalibrationStudy& s, const RaceStudy& r) {
  const std::string race = to_string(r.race);
  Figure f{"calibration-" + race,
           "Effective stiffness Q/δ^1.5 of the " + race + " contact over the calibrated load range",
           "ball load Q [N]",
           "Q / δ^1.5 [N/m^1.5]",
           true,
           false,
           {},
           {}};
  const auto q = loads(s.calibration, 25);
  for (const Law& law : laws(s, r.race)) {
    Series line{law.name, q, {}, "line"};
    for (double x : q) line.y.push_back(x / std::pow(law.approach(x), 1.5));
    f.series.push_back(line);
  }
  for (const FeCurve& c : r.curves) {
    Series pts{c.label, c.force, {}, "marker"};
    for (std::size_t i = 0; i < c.force.size(); ++i)
      pts.y.push_back(c.force[i] / std::pow(c.approach[i], 1.5));
    f.series.push_back(pts);
  }
  return f;
}

const ChannelSummary* channel(const RunSummary& s, const std::string& name) {
  for (const auto& c : s.channels)
    if (c.name == name) return &c;
  return nullptr;
}

Figure spectrum_figure(const CalibrationStudy& s) {
  Figure f{"calibration-spectra",
           "Vertical displacement spectrum under each contact law",
           "frequency [Hz]",
           "amplitude of y [m]",
           false,
           true,
           {},
           {},
           Panel::spectrum};
  for (const auto& r : s.responses) {
    for (std::size_t k = 0; k < r.summary.spectrum_channels.size(); ++k) {
      if (r.summary.spectrum_channels[k] != "y") continue;
      const auto& sp = r.summary.spectra[k];
      Series line{r.law, {}, {}, "line"};
      for (std::size_t i = 1; i < sp.frequency.size() && sp.frequency[i] <= 1000; ++i) {
        line.x.push_back(sp.frequency[i]);
        line.y.push_back(std::max(sp.amplitude[i], 1e-16));
      }
      f.series.push_back(line);
    }
  }
  return f;
}

// The laws table of one race: rows = laws and FE curves, columns = loads; δ [µm] and its
// difference from the calibrated law.
std::vector<std::vector<std::string>> race_table(const CalibrationStudy& s, const RaceStudy& r,
                                                 nlohmann::json& j) {
  const auto q = loads(s.calibration, 4);
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> head = {"law", "K [N/m^n]", "n"};
  for (double x : q) head.push_back("δ at " + fmt("%.4g", x) + " N [µm] (vs calibrated)");
  rows.push_back(head);
  const auto all = laws(s, r.race);
  const Law& cal = all.front();
  auto add = [&](const std::string& name, double K, double n, auto approach) {
    std::vector<std::string> row = {name, fmt("%.5e", K), fmt("%.5f", n)};
    nlohmann::json jr = {
        {"law", name}, {"K", K}, {"exponent", n}, {"approach", nlohmann::json::array()}};
    for (double x : q) {
      const double d = approach(x);
      row.push_back(fmt("%.5f", d * 1e6) + " (" + fmt("%+.2f", 100 * (d / cal.approach(x) - 1)) +
                    " %)");
      jr["approach"].push_back(std::isfinite(d) ? nlohmann::json(d) : nlohmann::json());
    }
    rows.push_back(row);
    j["laws"].push_back(jr);
  };
  for (const Law& law : all)
    add(law.name, law.K, law.exponent, [&](double x) { return law.approach(x); });
  for (const FeCurve& c : r.curves)
    add(c.label + " (points)", NAN, NAN, [&](double x) { return fe_approach(c, x); });
  j["loads"] = q;
  return rows;
}

std::vector<std::vector<std::string>> response_table(const CalibrationStudy& s, nlohmann::json& j) {
  std::vector<std::vector<std::string>> rows = {
      {"law", "series K [N/m^n]", "n", "RMS x [m]", "RMS y [m]", "largest peaks of y [Hz: m]"}};
  for (const auto& r : s.responses) {
    const ChannelSummary* x = channel(r.summary, "x");
    const ChannelSummary* y = channel(r.summary, "y");
    std::string peaks;
    nlohmann::json jp = nlohmann::json::array();
    for (std::size_t k = 0; y && k < y->peaks.size() && k < 3; ++k) {
      const auto& p = y->peaks[k];
      peaks += (k ? "; " : "") + fmt("%.2f", p.frequency) +
               (p.label.empty() ? "" : " (" + p.label + ")") + ": " + fmt("%.3e", p.amplitude);
      jp.push_back({{"frequency", p.frequency}, {"amplitude", p.amplitude}, {"label", p.label}});
    }
    const double rx = x ? x->statistics.rms : NAN, ry = y ? y->statistics.rms : NAN;
    rows.push_back({r.law, fmt("%.5e", r.contact.K), fmt("%.5f", r.contact.exponent),
                    fmt("%.4e", rx), fmt("%.4e", ry), peaks});
    j.push_back({{"law", r.law},
                 {"K", r.contact.K},
                 {"exponent", r.contact.exponent},
                 {"rms_x", rx},
                 {"rms_y", ry},
                 {"peaks_y", jp}});
  }
  return rows;
}

void html_table(std::ostringstream& h, const std::vector<std::vector<std::string>>& rows) {
  h << "<div class=\"scroll\"><table><thead><tr>";
  for (const auto& c : rows.front()) h << "<th>" << escape_html(c) << "</th>";
  h << "</tr></thead><tbody>\n";
  for (std::size_t i = 1; i < rows.size(); ++i) {
    h << "<tr>";
    for (const auto& c : rows[i]) h << "<td>" << escape_html(c) << "</td>";
    h << "</tr>\n";
  }
  h << "</tbody></table></div>\n";
}

void md_table(std::ostringstream& m, const std::vector<std::vector<std::string>>& rows) {
  for (std::size_t i = 0; i < rows.size(); ++i) {
    m << "|";
    for (const auto& c : rows[i]) m << " " << c << " |";
    m << "\n";
    if (i == 0) {
      m << "|";
      for (std::size_t k = 0; k < rows[0].size(); ++k) m << "---|";
      m << "\n";
    }
  }
  m << "\n";
}

void write_atomically(const fs::path& path, const std::string& text) {
  const fs::path tmp = path.string() + ".partial";
  {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
  }
  fs::rename(tmp, path);
}

}  // namespace

void write_calibration_report(const CalibrationStudy& s, const std::string& dir) {
  const fs::path out(dir), figures = out / "figures";
  fs::create_directories(figures);
  const RunInfo info = run_info("calibrate", "-", "", 1, 1, "");
  nlohmann::json j = {{"format", "bearing-verify calibration report 1"},
                      {"case", s.case_path},
                      {"bearing", s.bearing.designation},
                      {"geometry", s.geometry},
                      {"mesh", s.mesh},
                      {"commit", info.commit},
                      {"date", info.date},
                      {"load_range", {s.calibration.load_min, s.calibration.load_max}},
                      {"races", nlohmann::json::array()}};
  std::vector<Figure> figs;
  std::ostringstream h, m;
  h << html_head("bearing-verify calibration — " + s.bearing.designation);
  const std::string title = "Stiffness calibration of the " + s.bearing.designation;
  const std::string intro =
      "Case " + s.case_path + "; FE geometry fitted: " + s.geometry + " (" + s.mesh + "); loads " +
      fmt("%.4g", s.calibration.load_min) + " to " + fmt("%.4g", s.calibration.load_max) +
      " N (light load to the case's largest ball load); commit " + info.commit + ", " + info.date +
      ". calibration.json is read by bearing-sim with [model] contact = \"calibrated\", "
      "calibration = \"calibration.json\". δ is the elastic approach of one ball on the race.";
  h << "<h1>" << escape_html(title) << "</h1>\n<p>" << escape_html(intro) << "</p>\n";
  m << "# " << title << "\n\n" << intro << "\n\n";
  for (const RaceStudy& r : s.races) {
    nlohmann::json jr = {{"race", to_string(r.race)}, {"laws", nlohmann::json::array()}};
    const auto rows = race_table(s, r, jr);
    const std::string head =
        std::string("The ") + to_string(r.race) + " race: every law against the calibrated one";
    h << "<h2>" << escape_html(head) << "</h2>\n";
    html_table(h, rows);
    m << "## " << head << "\n\n";
    md_table(m, rows);
    figs.push_back(law_figure(s, r));
    j["races"].push_back(jr);
  }
  h << "<h2>The lumped response under each law</h2>\n";
  m << "## The lumped response under each law\n\n";
  if (s.static_case) {
    const std::string why =
        "The case is static (operation.speed = 0): the inner ring does not turn, so the lumped "
        "run only settles to its static state and has no vibration to compare between the laws. "
        "Their load-deflection curves are compared above; give operation.speed for the dynamic "
        "comparison.";
    h << "<p>" << escape_html(why) << "</p>\n";
    m << why << "\n\n";
    j["responses"] = nullptr;
    j["static_case"] = true;
  } else {
    nlohmann::json jresp = nlohmann::json::array();
    const auto rows = response_table(s, jresp);
    j["responses"] = jresp;
    j["static_case"] = false;
    figs.push_back(spectrum_figure(s));
    html_table(h, rows);
    md_table(m, rows);
  }
  draw_figures(figs, figures.string(), BEARING_VERIFY_PLOT_SCRIPT);
  h << "<h2>Figures</h2>\n";
  for (const auto& f : figs) {
    h << figure_html(f, figures.string()) << "\n";
    m << "![" << f.title << "](figures/" << f.name << ".png)\n\n";
  }
  h << "</body></html>\n";
  write_atomically(out / "calibration_report.json", j.dump(1) + "\n");
  write_atomically(out / "calibration_report.md", m.str());
  write_atomically(out / "calibration_report.html", h.str());
}

}  // namespace bearing::verify
