// _bearing: the compiled part of the Python package `bearing` (pybind11). A thin layer over the
// lumped library, composed as bearing-sim composes it (lumped/app/bearing_sim.cc): the same case
// reader and overrides, compute_info/info_json, simulate/summarize/summary_json, run_sweep. No
// physics here; python/bearing/__init__.py documents the API for users.

#include <gsl/gsl_errno.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "bearing/case_file.h"
#include "bearing/errors.h"
#include "bearing/info_report.h"
#include "bearing/output.h"
#include "bearing/presets.h"
#include "bearing/record_analysis.h"
#include "bearing/record_output.h"
#include "bearing/simulation.h"
#include "bearing/sweep.h"
#include "bearing/sweep_columns.h"
#include "bearing/units.h"

namespace py = pybind11;

namespace {

// ---------------------------------------------------------------------------------------------
// JSON → Python: the dicts of `info --json` and summary.json, number for number (a double stays
// the same double, so the dict equals json.load of the CLI's file).
py::object to_python(const nlohmann::json& j) {
  using T = nlohmann::json::value_t;
  switch (j.type()) {
    case T::null:
    case T::discarded:
      return py::none();
    case T::boolean:
      return py::bool_(j.get<bool>());
    case T::number_integer:
      return py::int_(j.get<std::int64_t>());
    case T::number_unsigned:
      return py::int_(j.get<std::uint64_t>());
    case T::number_float:
      return py::float_(j.get<double>());
    case T::string:
      return py::str(j.get_ref<const std::string&>());
    case T::array: {
      py::list out;
      for (const auto& e : j) out.append(to_python(e));
      return std::move(out);
    }
    case T::object: {
      py::dict out;
      for (const auto& [key, value] : j.items()) out[py::str(key)] = to_python(value);
      return std::move(out);
    }
    case T::binary:
      break;
  }
  throw std::runtime_error("unexpected JSON value");
}

// A read-only NumPy view of `data` that keeps `owner` (the Python object holding it) alive.
py::array view(const std::vector<double>& data, py::handle owner) {
  py::array a(py::dtype::of<double>(), {static_cast<py::ssize_t>(data.size())},
              {static_cast<py::ssize_t>(sizeof(double))}, data.data(), owner);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

// ---------------------------------------------------------------------------------------------
// A case as the CLI builds it: a file (or TOML text, or the built-in default) plus overrides,
// resolved again after every override so that errors surface where they are made.
struct CaseHandle {
  enum class Origin { file, text, builtin };
  Origin origin = Origin::builtin;
  std::string path;      // Origin::file: the file, as given
  std::string text;      // Origin::text: the TOML
  std::string base_dir;  // Origin::text: folder for relative table paths
  std::string source;    // Origin::text: the name used in messages
  std::vector<bearing::Override> overrides;
  bearing::Case resolved;

  // The case with `extra` overrides after this one's (a sweep point's).
  bearing::Case load(const std::vector<bearing::Override>& extra = {}) const {
    auto all = overrides;
    all.insert(all.end(), extra.begin(), extra.end());
    switch (origin) {
      case Origin::file:
        return bearing::read_case_file(path, all);
      case Origin::text:
        return bearing::parse_case(text, source, all, base_dir);
      case Origin::builtin:
        break;
    }
    return bearing::default_case(all);
  }
};

// A Python value as the text after '=' of `--set KEY=VALUE`: a str as it is (TOML, or else a
// string, as on the command line), True/False, numbers as Python prints them (shortest
// round-trip), a list or tuple as a TOML array (its strings quoted).
std::string toml_value(py::handle v, bool top) {
  if (py::isinstance<py::bool_>(v)) return v.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::int_>(v)) return py::str(v).cast<std::string>();
  if (py::isinstance<py::float_>(v)) return py::repr(v).cast<std::string>();
  if (py::isinstance<py::str>(v)) {
    const std::string s = v.cast<std::string>();
    if (top) return s;
    std::string out = "\"";
    for (char ch : s) {
      if (ch == '"' || ch == '\\') out += '\\';
      out += ch;
    }
    return out + "\"";
  }
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
    std::string out = "[";
    for (auto e : v) out += (out.size() > 1 ? ", " : "") + toml_value(e, false);
    return out + "]";
  }
  throw py::type_error("Case.set: a value must be a str, bool, int, float or a list of them, not " +
                       py::str(py::type::of(v)).cast<std::string>());
}

// ---------------------------------------------------------------------------------------------
// One run: the case, the simulation and its analysis, as bearing-sim run has them before writing.
struct RunResult {
  bearing::Case input;
  bearing::SimulationResult result;
  bearing::RunSummary summary;
  nlohmann::json summary_json;
};

std::unique_ptr<RunResult> run_case(const CaseHandle& c) {
  auto out = std::make_unique<RunResult>();
  out->input = c.resolved;
  py::gil_scoped_release release;
  out->result = bearing::simulate(out->input);
  out->summary = bearing::summarize(out->input, out->result);
  out->summary_json = bearing::summary_json(out->input, out->result, out->summary);
  return out;
}

// name → unit of every response channel, in response.csv's order (without t).
py::dict channel_units(const RunResult& r) {
  py::dict out;
  for (const auto& ch : r.result.response.channels) out[py::str(ch.name)] = ch.unit;
  return out;
}

py::array channel_view(py::object self, const std::string& name) {
  const auto& r = self.cast<const RunResult&>().result.response;
  for (std::size_t i = 0; i < r.channels.size(); ++i)
    if (r.channels[i].name == name) return view(r.values[i], self);
  std::string names;
  for (const auto& ch : r.channels) names += (names.empty() ? "" : ", ") + ch.name;
  throw py::key_error("no channel \"" + name + "\" in this run; its channels: " + names);
}

py::dict response_dict(py::object self) {
  const auto& r = self.cast<const RunResult&>().result.response;
  py::dict out;
  out["t"] = view(r.time, self);
  for (std::size_t i = 0; i < r.channels.size(); ++i)
    out[py::str(r.channels[i].name)] = view(r.values[i], self);
  return out;
}

py::dict spectrum_dict(py::object self) {
  const auto& s = self.cast<const RunResult&>().summary;
  py::dict out;
  if (s.spectra.empty()) return out;
  out["frequency"] = view(s.spectra.front().frequency, self);
  for (std::size_t i = 0; i < s.spectra.size(); ++i)
    out[py::str(s.spectrum_channels[i])] = view(s.spectra[i].amplitude, self);
  return out;
}

py::object envelope_dict(py::object self) {
  const auto& s = self.cast<const RunResult&>().summary;
  if (s.envelopes.empty()) return py::none();
  py::dict out;
  out["frequency"] = view(s.envelopes.front().spectrum.frequency, self);
  for (const auto& e : s.envelopes)
    out[py::str("env_" + e.channel)] = view(e.spectrum.amplitude, self);
  return std::move(out);
}

py::object pressure_dict(py::object self) {
  const auto& s = self.cast<const RunResult&>().summary;
  if (!s.noise) return py::none();
  py::dict out;
  out["t"] = view(s.noise->time, self);
  for (std::size_t m = 0; m < s.noise->pressure.size(); ++m)
    out[py::str("p" + std::to_string(m + 1))] = view(s.noise->pressure[m], self);
  return std::move(out);
}

// ---------------------------------------------------------------------------------------------
// Sweeps: an axis from "FROM:TO:N" (as --vary) or from a list of values (numbers SI, or strings
// with units).
bearing::SweepAxis sweep_axis(const std::string& key, py::handle spec) {
  if (py::isinstance<py::str>(spec))
    return bearing::parse_vary(key + "=" + spec.cast<std::string>());
  bearing::SweepAxis axis;
  axis.key = key;
  axis.dimension = bearing::key_dimension(key);  // InputError for a non-numeric key
  axis.integer = bearing::key_is_integer(key);
  for (auto e : spec) {
    const double v =
        py::isinstance<py::str>(e)
            ? bearing::parse_quantity(e.cast<std::string>(), axis.dimension, "vary " + key)
            : py::float_(py::reinterpret_borrow<py::object>(e)).cast<double>();
    if (axis.integer && v != std::round(v))
      throw bearing::InputError("vary " + key + ": " + key + " takes whole numbers, not " +
                                py::repr(e).cast<std::string>());
    axis.values.push_back(v);
  }
  if (axis.values.empty()) throw bearing::InputError("vary " + key + ": no values");
  return axis;
}

// The rows of sweep.csv as dicts, column for column: the varied keys, status, error, then the
// columns of the first successful row (bearing/sweep_columns.h: ring channels, microphones,
// envelopes, diagnosis), numbers as float, texts as str; empty CSV fields are None.
py::list sweep_rows(const std::vector<bearing::SweepAxis>& axes,
                    const std::vector<bearing::SweepRow>& rows) {
  bearing::SweepColumns columns;
  for (const auto& r : rows)
    if (r.ok) {
      columns = bearing::sweep_columns(r);
      break;
    }
  const std::vector<std::string> names = bearing::sweep_column_names(columns);
  py::list out;
  for (const auto& r : rows) {
    py::dict d;
    for (std::size_t a = 0; a < axes.size(); ++a)
      d[py::str(axes[a].key)] = axes[a].integer ? py::object(py::int_(std::llround(r.values[a])))
                                                : py::object(py::float_(r.values[a]));
    d["status"] = r.ok ? "ok" : "failed";
    d["error"] = r.error;
    const std::vector<bearing::SweepCell> cells = bearing::sweep_cells(columns, r);
    for (std::size_t i = 0; i < names.size(); ++i) {
      const bearing::SweepCell& cell = cells[i];
      if (const double* v = std::get_if<double>(&cell))
        d[py::str(names[i])] = py::float_(*v);
      else if (const std::string* text = std::get_if<std::string>(&cell))
        d[py::str(names[i])] = py::str(*text);
      else
        d[py::str(names[i])] = py::none();
    }
    out.append(std::move(d));
  }
  return out;
}

py::list sweep(const CaseHandle& c, const py::dict& vary, int jobs) {
  if (vary.empty())
    throw bearing::InputError(
        "vary: give at least one key, e.g. "
        "{\"operation.speed\": \"1000rpm:3000rpm:5\"}");
  if (jobs < 0) throw bearing::InputError("jobs = " + std::to_string(jobs) + ": must be >= 0");
  std::vector<bearing::SweepAxis> axes;
  for (const auto& [key, spec] : vary) axes.push_back(sweep_axis(key.cast<std::string>(), spec));
  std::vector<bearing::SweepRow> rows;
  const CaseHandle base = c;  // copied while the GIL is held: Python may change `c` meanwhile
  {
    py::gil_scoped_release release;
    const auto points = bearing::sweep_points(axes);
    const auto loader = [&base](const std::vector<bearing::Override>& p) { return base.load(p); };
    rows = bearing::run_sweep(loader, points, jobs);
  }
  return sweep_rows(axes, rows);
}

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
    const std::string& file, const std::string& speed_origin) {
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
  auto out = std::make_unique<AnalysisResult>();
  out->origin = {file, input.source, speed_origin};
  py::gil_scoped_release release;
  out->analysis = bearing::analyse_record(x, rate, channel, unit, input.bearing, sp, settings);
  out->summary_json = bearing::record_summary_json(out->analysis, out->origin);
  return out;
}

void bind_case(py::module_& m);
void bind_result(py::module_& m);
void bind_analysis(py::module_& m);

}  // namespace

PYBIND11_MODULE(_bearing, m) {
  // GSL's default handler aborts the process; the library checks GSL's return codes itself (as
  // bearing-sim's main does).
  gsl_set_error_handler_off();
  m.doc() = "Compiled core of the Python package bearing (see bearing.__doc__).";
  py::register_exception<bearing::InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<bearing::SolverError>(m, "SolverError", PyExc_RuntimeError);
  bind_case(m);
  bind_result(m);
  bind_analysis(m);

  m.def(
      "info",
      [](const CaseHandle& c) {
        const bearing::Case input = c.resolved;
        nlohmann::json j;
        {
          py::gil_scoped_release release;
          j = bearing::info_json(bearing::compute_info(input));
        }
        return to_python(j);
      },
      py::arg("case"), "The dict of `bearing-sim info --json` (SI units).");
  m.def("run", &run_case, py::arg("case"),
        "Simulates and analyses a case as `bearing-sim run` does (GIL released).");
  m.def("sweep", &sweep, py::arg("case"), py::arg("vary"), py::arg("jobs") = 0,
        "Runs the Cartesian product of `vary` with the C++ sweep's threads; rows of sweep.csv.");
  m.def("analyse", &analyse, py::arg("samples"), py::arg("rate"), py::arg("case"),
        py::arg("speed") = py::none(), py::arg("speed_source") = "option",
        py::arg("channel") = "record", py::arg("unit") = "m/s^2", py::arg("prewhiten") = false,
        py::arg("band") = "auto", py::arg("rule") = "line_to_floor", py::arg("false_alarm") = 1e-3,
        py::arg("slip") = 0.02, py::arg("harmonics") = 3, py::arg("file") = "",
        py::arg("speed_origin") = "",
        "Analyses a measured record as bearing-sim analyse does (GIL released).");
  m.def(
      "presets",
      [] {
        py::dict out;
        for (const auto& name : bearing::preset_names())
          out[py::str(name)] = bearing::preset_source(name);
        return out;
      },
      "Catalogue designation → where its numbers come from.");
  m.def("keys", &bearing::known_keys, "Every case-file key, as \"table.key\".");
  m.def("keys_help", &bearing::case_keys_help, "One line per key: what it is and its units.");
}

namespace {

void bind_case(py::module_& m) {
  using Origin = CaseHandle::Origin;
  py::class_<CaseHandle>(m, "Case",
                         "A resolved case: a file, TOML text or the default, plus overrides.")
      .def_static(
          "from_file",
          [](const std::string& path) {
            CaseHandle c;
            c.origin = Origin::file;
            c.path = path;
            c.resolved = c.load();
            return c;
          },
          py::arg("path"),
          "The case file at `path` (TOML; units as in README.md), resolved: its waviness tables "
          "and calibration file are read relative to its folder. Raises InputError naming the "
          "key, the value and what is allowed.")
      .def_static(
          "from_toml",
          [](const std::string& text, const std::string& base_dir, const std::string& source) {
            CaseHandle c;
            c.origin = Origin::text;
            c.text = text;
            c.base_dir = base_dir;
            c.source = source;
            c.resolved = c.load();
            return c;
          },
          py::arg("text"), py::arg("base_dir") = "", py::arg("source") = "TOML text",
          "A case from TOML text (plain numbers SI, strings may carry units); relative table "
          "paths are taken from `base_dir` (default: the working directory); `source` names it "
          "in messages and in summary['case']['source']. Raises InputError.")
      .def_static(
          "default",
          [] {
            CaseHandle c;
            c.resolved = c.load();
            return c;
          },
          "The built-in default case (bearing-sim without CASE): a 6308 at 2000 rpm under a 20 N "
          "downward radial load, 2-DOF, RK4 at dt = 5 us for 1.2 s (0.2 s transient), output at "
          "20 kHz.")
      .def(
          "set",
          [](CaseHandle& c, const std::string& key, const py::object& value) -> CaseHandle& {
            auto o = bearing::parse_override(key + "=" + toml_value(value, true));
            CaseHandle next = c;
            next.overrides.push_back(std::move(o));
            next.resolved = next.load();  // throws before anything changes
            c = std::move(next);
            return c;
          },
          py::arg("key"), py::arg("value"), py::return_value_policy::reference,
          "Overrides one case-file value, as `bearing-sim --set KEY=VALUE` does, and returns the "
          "case (so calls chain). `value`: a str as on the command line (TOML, or else a string "
          "that may carry a unit: \"3000 rpm\", \"2 um\", \"0.05 kN\"), a bool, an int or a "
          "float (SI), or a list of them (e.g. operation.load = [\"0 N\", \"-20 N\"]). A "
          "numeric part of `key` indexes an array of tables: \"waviness.inner.0.amplitude\". "
          "Raises InputError (the case is then unchanged).")
      .def(
          "to_toml", [](const CaseHandle& c) { return bearing::case_to_toml(c.resolved); },
          "The fully resolved case as TOML, every number in SI with 17 significant digits (the "
          "case.toml of a run: Case.from_toml(case.to_toml()) is the same case).")
      .def(
          "copy", [](const CaseHandle& c) { return c; },
          "An independent copy (set() on it leaves this case as it is).")
      .def("__copy__", [](const CaseHandle& c) { return c; })
      .def("__deepcopy__", [](const CaseHandle& c, py::dict) { return c; })
      .def_property_readonly(
          "source", [](const CaseHandle& c) { return c.resolved.source; },
          "The case file's path as given, \"built-in default case\", or from_toml's `source`.")
      .def_property_readonly(
          "overrides",
          [](const CaseHandle& c) {
            std::vector<std::pair<std::string, std::string>> out;
            for (const auto& o : c.overrides) out.emplace_back(o.key, o.value);
            return out;
          },
          "The overrides set() applied, in order, as (key, value text).")
      .def("__repr__", [](const CaseHandle& c) {
        std::string s = "bearing.Case(" + c.resolved.source;
        for (const auto& o : c.overrides) s += ", " + o.key + "=" + o.value;
        return s + ")";
      });
}

void bind_result(py::module_& m) {
  py::class_<RunResult>(m, "Result",
                        "One run of bearing.run(): the response (NumPy views, read-only, no "
                        "copies; SI), its spectra and summary.json's content.")
      .def_property_readonly(
          "t",
          [](py::object self) {
            return view(self.cast<const RunResult&>().result.response.time, self);
          },
          "Output times [s]: k / solver.output_rate from 0 to solver.duration (response.csv's t).")
      .def_property_readonly("channels", &channel_units,
                             "{name: SI unit} of every response channel in response.csv's "
                             "order (x, y [m], vx, vy [m/s], ax, ay [m/s^2], ...; without t).")
      .def("__getitem__", &channel_view, py::arg("name"),
           "One channel's samples at the times t, in its unit (channels[name]); KeyError for a "
           "name the run does not have.")
      .def(
          "__getattr__",
          [](py::object self, const std::string& name) {
            const auto& r = self.cast<const RunResult&>().result.response;
            for (std::size_t i = 0; i < r.channels.size(); ++i)
              if (r.channels[i].name == name) return view(r.values[i], self);
            throw py::attribute_error("bearing.Result has no attribute or channel \"" + name +
                                      "\"");
          },
          "result.ay is result[\"ay\"].")
      .def(
          "__contains__",
          [](const RunResult& r, const std::string& name) {
            for (const auto& ch : r.result.response.channels)
              if (ch.name == name) return true;
            return false;
          },
          "Whether the run has the channel `name`.")
      .def_property_readonly("response", &response_dict,
                             "{\"t\": times [s], name: samples [channel unit]}: response.csv "
                             "as views (pandas.DataFrame(result.response) makes the table).")
      .def_property_readonly("spectrum", &spectrum_dict,
                             "{\"frequency\": bins [Hz], ring channel: one-sided amplitude "
                             "[channel unit]} over [transient, duration) with output.window "
                             "(spectrum.csv).")
      .def_property_readonly("envelope", &envelope_dict,
                             "With output.envelope_band: {\"frequency\" [Hz], \"env_ax\", "
                             "... [m/s^2]} (envelope.csv); else None.")
      .def_property_readonly("pressure", &pressure_dict,
                             "With [acoustics]: {\"t\" [s] over [transient, duration), "
                             "\"p1\", ... [Pa] per microphone} (pressure.csv); else None.")
      .def_property_readonly(
          "summary", [](const RunResult& r) { return to_python(r.summary_json); },
          "summary.json's content as a new dict (SI; summary['units'] names them): case, "
          "contact, frequencies [Hz], channels.<name>.{mean,rms,ptp,kurtosis,crest,unit}, "
          "peaks.<name>[] {frequency [Hz], amplitude, label, label_error [Hz]}, solver, ...")
      .def_property_readonly(
          "case_toml", [](const RunResult& r) { return bearing::case_to_toml(r.input); },
          "The fully resolved case that ran, as TOML in SI (the run's case.toml).")
      .def(
          "write",
          [](const RunResult& r, const std::string& dir) {
            py::gil_scoped_release release;
            bearing::write_run(dir, r.input, r.result, r.summary);
          },
          py::arg("dir"),
          "Writes bearing-sim run's files into `dir` (created if missing; all or nothing): "
          "response, spectrum (CSV or .npy per output.format), summary.json, case.toml, ... "
          "Raises InputError if it cannot write.")
      .def(
          "__str__",
          [](const RunResult& r) { return bearing::summary_text(r.input, r.result, r.summary); },
          "bearing-sim run's readable summary (frequencies, RMS, PTP, kurtosis, peaks; units).")
      .def("__repr__", [](const RunResult& r) {
        return "<bearing.Result " + r.input.source + ": " +
               std::to_string(r.result.response.time.size()) + " samples, " +
               std::to_string(r.result.response.channels.size()) + " channels>";
      });
}

void bind_analysis(py::module_& m) {
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
          "The diagnosis: \"outer\", \"inner\", \"ball\" or \"none\".")
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

}  // namespace
