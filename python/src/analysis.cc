// bearing.analyse: a measured record (a NumPy array in SI) analysed as bearing-sim analyse does
// (analyse_record, record_summary_json, write_record_analysis); no physics here.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bearing/errors.h"
#include "bearing/record_analysis.h"
#include "bearing/record_output.h"
#include "bearing/units.h"
#include "bindings.h"

namespace bearing_python {

namespace {

// ---------------------------------------------------------------------------------------------
// A measured record analysed (bearing.analyse): the analysis, where it came from, its summary.
struct AnalysisResult {
  bearing::RecordAnalysis analysis;
  bearing::RecordOrigin origin;
  nlohmann::json summary_json;
};

// A frequency or angular speed given as a number (SI) or as a string with a unit.
double quantity_of(py::handle v, bearing::Dimension dim, const std::string& what) {
  if (py::isinstance<py::str>(v)) return bearing::parse_quantity(v.cast<std::string>(), dim, what);
  return py::float_(py::reinterpret_borrow<py::object>(v)).cast<double>();
}

// speed: None (the case's), "estimate" (near the case's), a number [rad/s] or "1797 rpm".
bearing::SpeedSetting speed_setting(const bearing::Case& c, py::handle speed,
                                    const std::string& source) {
  bearing::SpeedSetting s;
  s.speed = c.operation.speed;
  if (speed.is_none()) {
    s.source = bearing::SpeedSource::case_file;
    return s;
  }
  if (py::isinstance<py::str>(speed) && speed.cast<std::string>() == "estimate") {
    s.source = bearing::SpeedSource::estimate;
    return s;
  }
  s.speed = quantity_of(speed, bearing::Dimension::angular_speed, "speed");
  s.source = bearing::parse_named(bearing::kSpeedSources, source, "speed_source", "speed source");
  if (s.source == bearing::SpeedSource::estimate || s.source == bearing::SpeedSource::case_file)
    throw bearing::InputError("speed_source = \"" + source +
                              "\": a given speed comes from \"option\" or \"record\" (use "
                              "speed=\"estimate\" or speed=None for the others)");
  return s;
}

// band: "auto", "none", or (low, high) [Hz] as numbers or strings with units.
bearing::EnvelopeBandSetting band_setting(py::handle band) {
  bearing::EnvelopeBandSetting b;
  if (py::isinstance<py::str>(band)) {
    const std::string text = band.cast<std::string>();
    if (text == "auto") return b = {bearing::EnvelopeBandSource::automatic, {}};
    if (text == "none") return b = {bearing::EnvelopeBandSource::none, {}};
    throw bearing::InputError("band = \"" + text +
                              "\": allowed \"auto\", \"none\" or (low, high) in Hz");
  }
  const auto edges = band.cast<std::vector<py::object>>();
  if (edges.size() != 2)
    throw bearing::InputError("band: give (low, high) in Hz, \"auto\" or \"none\"");
  b.source = bearing::EnvelopeBandSource::given;
  b.band = {quantity_of(edges[0], bearing::Dimension::frequency, "band low"),
            quantity_of(edges[1], bearing::Dimension::frequency, "band high")};
  return b;
}

std::unique_ptr<AnalysisResult> analyse(
    py::array_t<double, py::array::c_style | py::array::forcecast> samples, double rate,
    const CaseHandle& c, py::handle speed, const std::string& speed_source,
    const std::string& channel, const std::string& unit, bool prewhiten, py::handle band,
    const std::string& rule, double false_alarm, double slip, int harmonics,
    double speed_refinement, const std::string& file, const std::string& speed_origin) {
  if (samples.ndim() != 1)
    throw bearing::InputError("samples: a 1-D array is needed, not " +
                              std::to_string(samples.ndim()) + "-D");
  std::vector<double> x(samples.data(), samples.data() + samples.size());
  const bearing::Case input = c.resolved;
  const bearing::SpeedSetting sp = speed_setting(input, speed, speed_source);
  bearing::RecordAnalysisSettings settings;
  settings.window = input.output.window;
  settings.peaks = input.output.peaks;
  settings.envelope = band_setting(band);
  settings.prewhiten = prewhiten;
  settings.rule = bearing::parse_named(bearing::kDiagnosisRules, rule, "rule", "diagnosis rule");
  settings.lines.false_alarm = false_alarm;
  settings.lines.slip = slip;
  settings.lines.harmonics = harmonics;
  settings.speed_refinement = speed_refinement;
  settings.coherence.slip = slip;
  if (settings.rule == bearing::DiagnosisRule::coherence)
    settings.coherence.false_alarm = false_alarm;
  auto out = std::make_unique<AnalysisResult>();
  out->origin.file = file;
  out->origin.case_source = input.source;
  out->origin.speed_origin = speed_origin;
  py::gil_scoped_release release;
  out->analysis = bearing::analyse_record(x, rate, channel, unit, input.bearing, sp, settings);
  out->summary_json = bearing::record_summary_json(out->analysis, out->origin);
  return out;
}

}  // namespace

void bind_analysis(py::module_& m) {
  m.def("analyse", &analyse, py::arg("samples"), py::arg("rate"), py::arg("case"),
        py::arg("speed") = py::none(), py::arg("speed_source") = "option",
        py::arg("channel") = "record", py::arg("unit") = "m/s^2", py::arg("prewhiten") = true,
        py::arg("band") = "auto", py::arg("rule") = "coherence", py::arg("false_alarm") = 1e-3,
        py::arg("slip") = 0.02, py::arg("harmonics") = 3, py::arg("speed_refinement") = 0.03,
        py::arg("file") = "", py::arg("speed_origin") = "",
        "Analyses a measured record as bearing-sim analyse does (GIL released).");

  py::class_<AnalysisResult>(m, "Analysis",
                             "One record analysed by bearing.analyse(): its spectra (NumPy views, "
                             "read-only) and summary.json's content.")
      .def_property_readonly(
          "summary", [](const AnalysisResult& r) { return to_python(r.summary_json); },
          "summary.json's content as a new dict (SI; summary['units'] names them).")
      .def_property_readonly(
          "family",
          [](const AnalysisResult& r) {
            return std::string(bearing::name_of(bearing::kFaultFamilies, r.analysis.family()));
          },
          "The diagnosis: \"outer\", \"inner\", \"ball\", \"several\" or \"none\".")
      .def_property_readonly(
          "margin",
          [](const AnalysisResult& r) { return r.summary_json["diagnosis"].value("margin", 0.0); },
          "The verdict's margin [dB]: how far its evidence stands over what it needs (a named "
          "family: > 0), or how far the nearest family falls short (none: <= 0).")
      .def_property_readonly(
          "coherence",
          [](const AnalysisResult& r) -> py::object {
            if (!r.summary_json.contains("coherence")) return py::none();
            return to_python(r.summary_json["coherence"]);
          },
          "The coherence diagnosis's evidence (summary['coherence']): bands [[low, high] Hz], "
          "levels, map {family: margin per band [dB], -100 unrated}, families {family: best "
          "band, harmonics (frequency [Hz], excess [dB]), decoys, side lines, margin [dB], "
          "named}; None without an envelope band.")
      .def_property_readonly(
          "spectrum",
          [](py::object self) {
            const auto& a = self.cast<const AnalysisResult&>().analysis;
            py::dict out;
            out["frequency"] = view(a.summary.spectra.front().frequency, self);
            out[py::str(a.channel)] = view(a.summary.spectra.front().amplitude, self);
            return out;
          },
          "{\"frequency\" [Hz], channel: one-sided amplitude [unit]} (spectrum.csv).")
      .def_property_readonly(
          "envelope",
          [](py::object self) -> py::object {
            const auto& a = self.cast<const AnalysisResult&>().analysis;
            if (a.summary.envelopes.empty()) return py::none();
            py::dict out;
            out["frequency"] = view(a.summary.envelopes.front().spectrum.frequency, self);
            out[py::str("env_" + a.channel)] =
                view(a.summary.envelopes.front().spectrum.amplitude, self);
            out[py::str("ses_" + a.channel)] = view(a.squared_envelope->amplitude, self);
            return std::move(out);
          },
          "With an envelope band: {\"frequency\" [Hz], \"env_<ch>\" [unit], \"ses_<ch>\" "
          "[unit^2]} (envelope.csv); else None.")
      .def(
          "write",
          [](const AnalysisResult& r, const std::string& dir, const std::string& format) {
            const auto f =
                bearing::parse_named(bearing::kOutputFormats, format, "format", "output format");
            py::gil_scoped_release release;
            bearing::write_record_analysis(dir, r.analysis, r.origin, f);
          },
          py::arg("dir"), py::arg("format") = "csv",
          "Writes spectrum, envelope (CSV or .npy), summary.json into `dir` (all or nothing).")
      .def("__str__",
           [](const AnalysisResult& r) {
             return bearing::record_summary_text(r.analysis, r.origin);
           })
      .def("__repr__", [](const AnalysisResult& r) {
        return "<bearing.Analysis " + r.analysis.channel + ": " +
               std::to_string(r.analysis.samples) + " samples, diagnosis " +
               bearing::name_of(bearing::kFaultFamilies, r.analysis.family()) + ">";
      });
}

}  // namespace bearing_python
