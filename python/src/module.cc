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
#include "bearing/simulation.h"
#include "bearing/stiffness.h"
#include "bearing/structure_modes.h"
#include "bearing/sweep.h"
#include "bearing/sweep_columns.h"
#include "bearing/units.h"
#include "bindings.h"

namespace py = pybind11;
using bearing_python::CaseHandle;
using bearing_python::to_python;
using bearing_python::view;

namespace bearing_python {

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

}  // namespace bearing_python

namespace {

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

// A matrix as a new 5×5 NumPy array.
py::array_t<double> matrix_array(const bearing::Matrix5& K) {
  py::array_t<double> a(std::vector<py::ssize_t>{5, 5});
  auto out = a.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < 5; ++i)
    for (py::ssize_t j = 0; j < 5; ++j) out(i, j) = K(i, j);
  return a;
}

// Matrices as a new n×5×5 NumPy array.
py::array_t<double> matrices_array(const std::vector<bearing::Matrix5>& Ks) {
  py::array_t<double> a(std::vector<py::ssize_t>{static_cast<py::ssize_t>(Ks.size()), 5, 5});
  auto out = a.mutable_unchecked<3>();
  for (py::ssize_t k = 0; k < out.shape(0); ++k)
    for (py::ssize_t i = 0; i < 5; ++i)
      for (py::ssize_t j = 0; j < 5; ++j) out(k, i, j) = Ks[k](i, j);
  return a;
}

// The case's point with its ball pass at `samples` cage angles (4 … kMaxBallPassSamples).
bearing::StiffnessPoint point_with_ball_pass(const CaseHandle& c, int samples) {
  if (samples < 4 || samples > bearing::kMaxBallPassSamples)
    throw bearing::InputError(
        "samples = " + std::to_string(samples) + ": allowed an integer from 4 to " +
        std::to_string(bearing::kMaxBallPassSamples) + " (cage angles through one ball pitch)");
  const bearing::Case input = c.resolved;
  py::gil_scoped_release release;
  return bearing::stiffness_point(input, samples);
}

// bearing.stiffness: the rotor's K (averaged over one ball pass) and why it is singular, if it is.
py::tuple rotor_stiffness(const CaseHandle& c, int samples) {
  const bearing::StiffnessPoint p = point_with_ball_pass(c, samples);
  return py::make_tuple(matrix_array(p.rotor->stiffness), p.rotor->warnings);
}

// bearing.ball_pass_stiffness: the case's point with its ball pass, as NumPy arrays.
py::dict ball_pass_stiffness(const CaseHandle& c, int samples) {
  const bearing::StiffnessPoint p = point_with_ball_pass(c, samples);
  const bearing::BallPassStiffness& b = *p.ball_pass;
  py::dict out;
  out["cage_angles"] =
      py::array_t<double>(static_cast<py::ssize_t>(b.cage_angles.size()), b.cage_angles.data());
  out["samples"] = matrices_array(b.samples);
  out["mean"] = matrix_array(b.mean);
  out["min"] = matrix_array(b.min);
  out["max"] = matrix_array(b.max);
  out["harmonics"] = matrices_array(b.harmonics);
  out["damping_samples"] = matrices_array(b.damping_samples);
  out["damping_mean"] = matrix_array(b.damping_mean);
  out["bpfo"] = p.bpfo;
  return out;
}

// bearing.modes: a modes file of bearing-fem modes read by the C++ reader (the same checks as
// [housing] modes), its per-mode arrays as NumPy arrays [M, 3].
py::dict read_modes(const std::string& path) {
  const bearing::StructureModes m =
      bearing::read_structure_modes(path, "bearing.modes(\"" + path + "\")");
  const auto xyz = [&](const std::array<std::vector<double>, 3>& shape) {
    py::array_t<double> a({static_cast<py::ssize_t>(m.count()), py::ssize_t{3}});
    auto w = a.mutable_unchecked<2>();
    for (int k = 0; k < m.count(); ++k)
      for (int i = 0; i < 3; ++i) w(k, i) = shape[static_cast<std::size_t>(i)][k];
    return a;
  };
  py::dict sensors;
  for (const bearing::StructureSensor& s : m.sensors) {
    py::dict d;
    d["point"] = py::array_t<double>(3, s.point.data());
    d["shape"] = xyz(s.shape);
    sensors[py::str(s.name)] = d;
  }
  py::dict out;
  out["file"] = m.path;
  out["free"] = m.free;
  out["frequencies"] = py::array_t<double>(m.frequencies.size(), m.frequencies.data());
  out["seat"] = xyz(m.seat);
  out["sensors"] = sensors;
  return out;
}

void bind_case(py::module_& m);
void bind_result(py::module_& m);

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
  bearing_python::bind_analysis(m);

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
  m.def("stiffness", &rotor_stiffness, py::arg("case"),
        py::arg("samples") = bearing::kBallPassSamples,
        "The 5x5 stiffness K = dF/dq at the case's operating point averaged over one ball pass "
        "at `samples` cage angles (bearing/rotor_coefficients.h), SI, and the warnings about it: "
        "(matrix, [str]).");
  m.def(
      "stiffness_at_cage_angle",
      [](const CaseHandle& c) {
        const bearing::Case input = c.resolved;
        bearing::StiffnessPoint p;
        {
          py::gil_scoped_release release;
          p = bearing::stiffness_point(input, 0);  // the matrix at the cage angle alone
        }
        return matrix_array(p.solution.at.stiffness);
      },
      py::arg("case"),
      "The 5x5 stiffness K = dF/dq at the case's operating point and cage angle "
      "(bearing/stiffness.h), SI.");
  m.def(
      "damping",
      [](const CaseHandle& c, int samples) {
        return matrix_array(point_with_ball_pass(c, samples).rotor->damping);
      },
      py::arg("case"), py::arg("samples") = bearing::kBallPassSamples,
      "The 5x5 damping C = dF/d(dq/dt) of the EHL squeeze films at the case's operating point "
      "averaged over one ball pass at `samples` cage angles (bearing/rotor_coefficients.h), SI; "
      "0 without [lubricant].");
  m.def(
      "damping_at_cage_angle",
      [](const CaseHandle& c) {
        const bearing::Case input = c.resolved;
        bearing::StiffnessPoint p;
        {
          py::gil_scoped_release release;
          p = bearing::stiffness_point(input, 0);
        }
        return matrix_array(p.solution.at.damping);
      },
      py::arg("case"),
      "The 5x5 damping C at the case's operating point and cage angle (five_dof_static.h), SI.");
  m.def("ball_pass_stiffness", &ball_pass_stiffness, py::arg("case"),
        py::arg("samples") = bearing::kBallPassSamples,
        "K over one ball pass at `samples` cage angles (bearing/ball_pass_stiffness.h), SI: a "
        "dict of NumPy arrays.");
  m.def("read_modes", &read_modes, py::arg("path"),
        "A modes file of bearing-fem modes (bearing/structure_modes.h), SI: a dict of NumPy "
        "arrays.");
  m.def("run", &run_case, py::arg("case"),
        "Simulates and analyses a case as `bearing-sim run` does (GIL released).");
  m.def("sweep", &sweep, py::arg("case"), py::arg("vary"), py::arg("jobs") = 0,
        "Runs the Cartesian product of `vary` with the C++ sweep's threads; rows of sweep.csv.");
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
          "update",
          [](CaseHandle& c, const py::dict& values) -> CaseHandle& {
            CaseHandle next = c;
            for (const auto& [key, value] : values)
              next.overrides.push_back(bearing::parse_override(
                  py::str(key).cast<std::string>() + "=" +
                  toml_value(py::reinterpret_borrow<py::object>(value), true)));
            next.resolved = next.load();  // once, all set: a table whose keys need each other
            c = std::move(next);
            return c;
          },
          py::arg("values"), py::return_value_policy::reference,
          "Overrides several case-file values at once, {key: value} as set() takes them, and "
          "returns the case; the case is resolved once with all of them, so keys that need each "
          "other (a new [lubricant] table's viscosity, pressure_viscosity and roughness) can be "
          "given together. Raises InputError (the case is then unchanged).")
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

}  // namespace
