#include "bearing/case_file.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include <toml++/toml.h>

#include "bearing/calibration.h"
#include "bearing/errors.h"
#include "bearing/hertz.h"
#include "bearing/presets.h"
#include "edit_distance.h"

namespace bearing {

namespace {

// ---------------------------------------------------------------------------------------------
// The schema: every key the reader accepts, with its dimension. The readers below ask for keys by
// these names; unknown keys are what is left over. Entries of an array of tables
// ([[waviness.inner]]) are named "waviness.inner.<key>" here and "waviness.inner[i].<key>" in
// messages.
// ---------------------------------------------------------------------------------------------
enum class Kind { quantity, integer, text, boolean, vector2, list, points, table, table_array };

struct KeySpec {
  const char* name;
  Kind kind;
  Dimension dim;
  const char* help;
};

const std::vector<KeySpec>& schema() {
  using D = Dimension;
  static const std::vector<KeySpec> keys{
      {"bearing.preset", Kind::text, D::dimensionless,
       "catalogue bearing (608, 6304, 6308, 6205, 209); other keys override it"},
      {"bearing.ball_diameter", Kind::quantity, D::length, "ball diameter D"},
      {"bearing.pitch_diameter", Kind::quantity, D::length, "pitch diameter d_m"},
      {"bearing.balls", Kind::integer, D::dimensionless, "number of balls Z (>= 3)"},
      {"bearing.inner_conformity", Kind::quantity, D::dimensionless,
       "inner groove radius / D (> 0.5)"},
      {"bearing.outer_conformity", Kind::quantity, D::dimensionless,
       "outer groove radius / D (> 0.5)"},
      {"bearing.clearance", Kind::quantity, D::length,
       "ISO radial internal clearance P_d (diametral); each ball's gap is P_d/2"},
      {"bearing.contact_angle", Kind::quantity, D::angle, "free contact angle alpha"},
      {"material.young", Kind::quantity, D::pressure, "Young's modulus, balls and rings"},
      {"material.poisson", Kind::quantity, D::dimensionless, "Poisson ratio in (-1, 0.5)"},
      {"material.density", Kind::quantity, D::density, "density"},
      {"material.ball", Kind::table, D::dimensionless, "ball material (young, poisson, density)"},
      {"material.rings", Kind::table, D::dimensionless, "ring material (young, poisson, density)"},
      {"material.ball.young", Kind::quantity, D::pressure, "ball Young's modulus"},
      {"material.ball.poisson", Kind::quantity, D::dimensionless, "ball Poisson ratio"},
      {"material.ball.density", Kind::quantity, D::density, "ball density"},
      {"material.rings.young", Kind::quantity, D::pressure, "ring Young's modulus"},
      {"material.rings.poisson", Kind::quantity, D::dimensionless, "ring Poisson ratio"},
      {"material.rings.density", Kind::quantity, D::density, "ring density"},
      {"rotor.mass", Kind::quantity, D::mass, "inner ring + shaft mass (default 0.6 kg)"},
      {"rotor.damping", Kind::quantity, D::damping, "radial damping (default 200 N s/m)"},
      {"rotor.axial_mass", Kind::quantity, D::mass, "axial mass, 3dof (default: rotor.mass)"},
      {"rotor.axial_damping", Kind::quantity, D::damping,
       "axial damping, 3dof (default: rotor.damping)"},
      {"operation.speed", Kind::quantity, D::angular_speed, "inner-ring speed"},
      {"operation.load", Kind::vector2, D::force,
       "radial load [Fx, Fy] on the inner ring (y up: Fy < 0 pushes down)"},
      {"operation.axial_load", Kind::quantity, D::force, "axial load / preload Fz, 3dof"},
      {"operation.unbalance", Kind::quantity, D::mass_length,
       "unbalance m_u e; force m_u e w^2 rotating with the shaft"},
      {"operation.gravity", Kind::boolean, D::dimensionless, "add the rotor weight -m g to Fy"},
      {"waviness.inner", Kind::table_array, D::dimensionless,
       "[[waviness.inner]] entries: order, amplitude, phase; or table = \"file.csv\""},
      {"waviness.outer", Kind::table_array, D::dimensionless,
       "[[waviness.outer]] entries: order, amplitude, phase; or table = \"file.csv\""},
      {"waviness.inner.order", Kind::integer, D::dimensionless, "waves per revolution (>= 1)"},
      {"waviness.inner.amplitude", Kind::quantity, D::length, "waviness amplitude"},
      {"waviness.inner.phase", Kind::quantity, D::angle, "waviness phase"},
      {"waviness.inner.table", Kind::text, D::dimensionless,
       "CSV order,amplitude[,phase] (um, deg unless the header says)"},
      {"waviness.outer.order", Kind::integer, D::dimensionless, "waves per revolution (>= 1)"},
      {"waviness.outer.amplitude", Kind::quantity, D::length, "waviness amplitude"},
      {"waviness.outer.phase", Kind::quantity, D::angle, "waviness phase"},
      {"waviness.outer.table", Kind::text, D::dimensionless,
       "CSV order,amplitude[,phase] (um, deg unless the header says)"},
      {"ball_errors.values", Kind::list, D::length,
       "each ball's diameter deviation D_j - D (one per ball)"},
      {"ball_errors.band", Kind::quantity, D::length,
       "draw D_j - D uniformly in [-band/2, band/2]"},
      {"ball_errors.seed", Kind::integer, D::dimensionless, "seed of the band draw (default 1)"},
      {"model.kind", Kind::text, D::dimensionless,
       "2dof | 3dof | balls (seed 004: ball DOFs, cage slip, friction) | quasistatic (seed 000: "
       "equilibrium per output instant, no [solver] method)"},
      {"model.contact", Kind::text, D::dimensionless,
       "contact law: exact | hamrock-brewe | harris-table | calibrated"},
      {"model.calibration", Kind::text, D::dimensionless,
       "FE constants for contact = \"calibrated\": the JSON of bearing-fem calibrate"},
      {"model.waviness_stiffness", Kind::boolean, D::dimensionless,
       "TVDS: contact stiffness follows the waviness curvature (default false: TVD)"},
      {"cage.slip", Kind::quantity, D::dimensionless,
       "balls: cage slip s_c in [0, 1), cage at (1 - s_c) x its pure-rolling speed (default 0)"},
      {"cage.friction", Kind::quantity, D::dimensionless,
       "balls: traction coefficient mu_m reached at cage.slide_speed (default 0.01)"},
      {"cage.slide_speed", Kind::quantity, D::velocity,
       "balls: sliding speed where traction saturates (default 0.1 m/s)"},
      {"ball.mass", Kind::quantity, D::mass, "balls: ball mass (default: density x pi D^3/6)"},
      {"ball.inertia", Kind::quantity, D::inertia,
       "balls: ball moment of inertia (default: mass x D^2/10)"},
      {"ball.damping", Kind::quantity, D::damping,
       "balls: damping of each ball's radial motion (default: rotor.damping)"},
      {"ball.centrifugal", Kind::boolean, D::dimensionless,
       "balls: centrifugal load m_b w_cage^2 d_m/2 on each ball (default true)"},
      {"solver.method", Kind::text, D::dimensionless, "rk4 | rkf45 | rk8pd | newmark | bdf"},
      {"solver.dt", Kind::quantity, D::time, "time step, or first step (default 5 us)"},
      {"solver.duration", Kind::quantity, D::time, "simulated time (default 1.2 s)"},
      {"solver.transient", Kind::quantity, D::time, "discarded before statistics (default 0.2 s)"},
      {"solver.tolerance", Kind::quantity, D::dimensionless,
       "relative tolerance, adaptive/bdf/newmark (default 1e-6)"},
      {"solver.output_rate", Kind::quantity, D::frequency, "samples written per second (20 kHz)"},
      {"solver.max_displacement", Kind::quantity, D::length,
       "blow-up bound on the ring displacement (default 1 mm)"},
      {"output.ball_loads", Kind::boolean, D::dimensionless, "write each ball's load Q1..QZ"},
      {"output.ball_motion", Kind::boolean, D::dimensionless,
       "write each ball centre's radial displacement r1..rZ [m] and velocity vr1..vrZ [m/s]"},
      {"output.ball_approach", Kind::boolean, D::dimensionless,
       "write each ball's approach d1..dZ [m] (positive: elastic approach; negative: gap)"},
      {"output.ball_dynamics", Kind::boolean, D::dimensionless,
       "balls: write each ball's spin wb [rad/s], outer load Qo [N], friction Fi, Fo [N]"},
      {"output.window", Kind::text, D::dimensionless, "hann | flattop | rectangular"},
      {"output.peaks", Kind::integer, D::dimensionless, "peaks listed per channel (default 10)"},
      {"acoustics.ring_source", Kind::text, D::dimensionless,
       "inner ring as: cylinder-dipole (default) | paper | none"},
      {"acoustics.ball_source", Kind::text, D::dimensionless,
       "each ball as: oscillating-sphere (default) | pulsating-sphere | paper | none"},
      {"acoustics.summation", Kind::text, D::dimensionless,
       "coherent (default: sum of pressures) | energetic (seed 000: sqrt of summed squares)"},
      {"acoustics.microphones", Kind::points, D::length,
       "[[r, angle], ...] in the bearing plane from the bearing centre, angle from +x towards +y"},
      {"acoustics.ring_radius", Kind::quantity, D::length,
       "radiating radius of the inner ring (default: inner raceway radius (d_m - D)/2)"},
      {"acoustics.density", Kind::quantity, D::density, "air density (default 1.204 kg/m^3)"},
      {"acoustics.sound_speed", Kind::quantity, D::velocity, "speed of sound (default 343.2 m/s)"},
  };
  return keys;
}

const std::vector<std::string>& top_tables() {
  static const std::vector<std::string> t{"bearing",  "material",    "rotor",  "operation",
                                          "waviness", "ball_errors", "model",  "cage",
                                          "ball",     "solver",      "output", "acoustics"};
  return t;
}

const KeySpec* find_spec(const std::string& name) {
  for (const auto& k : schema())
    if (name == k.name) return &k;
  return nullptr;
}

std::string last_part(const std::string& dotted) {
  const auto dot = dotted.rfind('.');
  return dot == std::string::npos ? dotted : dotted.substr(dot + 1);
}

// The nearest known name to an unknown "table.key": the same key in another table, or the
// closest spelling.
std::string suggestion(const std::string& unknown) {
  const std::string leaf = last_part(unknown);
  for (const auto& k : schema())
    if (leaf == last_part(k.name) && unknown != k.name) return k.name;
  std::string best;
  std::size_t best_d = std::string::npos;
  for (const auto& k : schema()) {
    const std::size_t d = detail::edit_distance(unknown, k.name);
    if (d < best_d) best_d = d, best = k.name;
  }
  for (const auto& t : top_tables()) {
    const std::size_t d = detail::edit_distance(unknown, t);
    if (d < best_d) best_d = d, best = t;
  }
  const std::size_t limit = std::max<std::size_t>(2, leaf.size() / 3 + 1);
  return best_d <= limit ? best : std::string();
}

std::string keys_of_table(const std::string& table) {
  std::string out;
  for (const auto& k : schema()) {
    const std::string n = k.name;
    if (n.rfind(table + ".", 0) == 0 && n.find('.', table.size() + 1) == std::string::npos)
      out += (out.empty() ? "" : ", ") + n.substr(table.size() + 1);
  }
  return out;
}

// `name` is the schema name of the unknown key, `shown` how the user wrote it.
[[noreturn]] void unknown_key(const std::string& name, const std::string& shown) {
  const auto dot = name.rfind('.');
  const std::string table = dot == std::string::npos ? std::string() : name.substr(0, dot);
  std::string msg;
  const std::string s = suggestion(name);
  if (table.empty() || keys_of_table(table).empty()) {
    msg = "unknown table or key \"" + shown + "\"";
    if (!s.empty()) msg += "; did you mean \"" + s + "\"?";
    msg += " Known tables:";
    for (const auto& t : top_tables()) msg += " [" + t + "]";
  } else {
    msg = "unknown key \"" + shown + "\"";
    if (!s.empty()) msg += "; did you mean \"" + s + "\"?";
    msg += " Keys of [" + table + "]: " + keys_of_table(table);
  }
  throw InputError(msg);
}

std::string type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a number";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::table:
      return "a table";
    default:
      return "a date or time";
  }
}

std::string shown_value(const toml::node& node) {
  std::ostringstream s;
  if (node.is_string())
    s << '"' << node.value<std::string>().value() << '"';
  else if (node.is_table())
    s << "{...}";
  else
    node.visit([&s](auto&& n) { s << n; });
  return s.str();
}

std::string join(const std::vector<std::string>& items) {
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "" : ", ") + i;
  return s;
}

// A quantity: a plain number (SI) or a string with a unit.
double read_quantity(const toml::node& node, const std::string& key, Dimension dim) {
  if (node.is_integer() || node.is_floating_point()) {
    const double v = node.value<double>().value();
    if (!std::isfinite(v))
      throw InputError(key + " = " + shown_value(node) + ": must be a finite number");
    if (dim != Dimension::dimensionless && !bare_number_is_si(dim) && v != 0.0)
      throw InputError(key + " = " + shown_value(node) + ": missing unit; an " +
                       std::string(dimension_name(dim)) +
                       " needs one because a bare number is ambiguous, e.g. \"" +
                       shown_value(node) + " " + accepted_units(dim).back() +
                       "\" (accepted units: " + join(accepted_units(dim)) + ")");
    return v;
  }
  if (node.is_string()) return parse_quantity(node.value<std::string>().value(), dim, key);
  const std::string expected = dim == Dimension::dimensionless
                                   ? std::string("a number")
                                   : "a number in " + std::string(si_unit(dim)) +
                                         " or a string with a unit such as \"1 " +
                                         accepted_units(dim).front() + "\"";
  throw InputError(key + " = " + shown_value(node) + ": expected " + expected + ", got " +
                   type_name(node));
}

// Reads the keys of one table, remembering which were used so the rest can be reported.
class TableReader {
 public:
  /// `shown` names the table in messages ("waviness.inner[2]"), `schema` in the schema
  /// ("waviness.inner").
  TableReader(const toml::table* table, std::string shown, std::string schema = "")
      : table_(table), shown_(std::move(shown)), schema_(schema.empty() ? shown_ : schema) {}

  const toml::node* get(const char* key) {
    used_.push_back(key);
    return table_ ? table_->get(key) : nullptr;
  }
  std::string full(const char* key) const { return shown_ + "." + key; }
  bool has(const char* key) const { return table_ && table_->get(key); }

  std::optional<double> quantity(const char* key) {
    const toml::node* n = get(key);
    if (!n) return std::nullopt;
    return read_quantity(*n, full(key), spec(key).dim);
  }
  std::optional<long long> integer(const char* key) {
    const toml::node* n = get(key);
    if (!n) return std::nullopt;
    if (n->is_integer()) return n->value<long long>().value();
    if (n->is_floating_point()) {
      const double v = n->value<double>().value();
      throw InputError(
          full(key) + " = " + shown_value(*n) + ": expected a whole number (" + spec(key).help +
          ")" +
          (std::isfinite(v) && v == std::floor(v) ? ", write it without a decimal point" : ""));
    }
    throw InputError(full(key) + " = " + shown_value(*n) + ": expected an integer (" +
                     spec(key).help + "), got " + type_name(*n));
  }
  std::optional<std::string> text(const char* key, bool allow_integer = false) {
    const toml::node* n = get(key);
    if (!n) return std::nullopt;
    if (n->is_string()) return n->value<std::string>().value();
    if (allow_integer && n->is_integer()) return std::to_string(n->value<long long>().value());
    throw InputError(full(key) + " = " + shown_value(*n) + ": expected a string (" +
                     spec(key).help + "), got " + type_name(*n));
  }
  // A text that must be one of `allowed`.
  std::optional<std::string> choice(const char* key, const std::vector<std::string>& allowed) {
    auto v = text(key);
    if (v && std::find(allowed.begin(), allowed.end(), *v) == allowed.end())
      throw InputError(full(key) + " = \"" + *v + "\": allowed: " + join(allowed));
    return v;
  }
  std::optional<bool> boolean(const char* key) {
    const toml::node* n = get(key);
    if (!n) return std::nullopt;
    if (n->is_boolean()) return n->value<bool>().value();
    throw InputError(full(key) + " = " + shown_value(*n) + ": expected true or false (" +
                     spec(key).help + "), got " + type_name(*n));
  }
  std::optional<Eigen::Vector2d> vector2(const char* key) {
    const toml::node* n = get(key);
    if (!n) return std::nullopt;
    const toml::array* a = n->as_array();
    if (!a || a->size() != 2)
      throw InputError(full(key) + " = " + shown_value(*n) + ": expected two values [x, y] (" +
                       spec(key).help + "), e.g. [\"0 N\", \"-500 N\"]");
    Eigen::Vector2d v;
    for (int i = 0; i < 2; ++i)
      v[i] = read_quantity(*a->get(i), full(key) + "[" + std::to_string(i) + "]", spec(key).dim);
    return v;
  }
  std::optional<std::vector<double>> list(const char* key) {
    const toml::node* n = get(key);
    if (!n) return std::nullopt;
    const toml::array* a = n->as_array();
    if (!a)
      throw InputError(full(key) + " = " + shown_value(*n) + ": expected an array (" +
                       spec(key).help + "), e.g. [\"1 um\", \"-0.5 um\", ...]");
    std::vector<double> v;
    for (std::size_t i = 0; i < a->size(); ++i)
      v.push_back(
          read_quantity(*a->get(i), full(key) + "[" + std::to_string(i) + "]", spec(key).dim));
    return v;
  }
  // An array of [r, angle] pairs: a length and an angle each.
  std::optional<std::vector<Microphone>> points(const char* key) {
    const toml::node* n = get(key);
    if (!n) return std::nullopt;
    const toml::array* a = n->as_array();
    const auto bad = [&](const std::string& what) {
      return InputError(full(key) + " = " + shown_value(*n) + ": " + what + " (" + spec(key).help +
                        "), e.g. [[\"10 mm\", \"-90 deg\"], [\"0.5 m\", \"0 deg\"]]");
    };
    if (!a) throw bad("expected an array of [r, angle] pairs");
    std::vector<Microphone> out;
    for (std::size_t i = 0; i < a->size(); ++i) {
      const toml::array* p = a->get(i)->as_array();
      if (!p || p->size() != 2)
        throw bad("entry " + std::to_string(i) + " is not a pair [r, angle]");
      const std::string shown = full(key) + "[" + std::to_string(i) + "]";
      out.push_back({read_quantity(*p->get(0), shown + "[0] (r)", Dimension::length),
                     read_quantity(*p->get(1), shown + "[1] (angle)", Dimension::angle)});
    }
    return out;
  }
  const toml::table* subtable(const char* key) {
    const toml::node* n = get(key);
    if (!n) return nullptr;
    if (!n->is_table())
      throw InputError(full(key) + " = " + shown_value(*n) + ": expected a table [" + full(key) +
                       "] with " + keys_of_table(schema_ + "." + key) + ", got " + type_name(*n));
    return n->as_table();
  }
  const toml::array* table_array(const char* key) {
    const toml::node* n = get(key);
    if (!n) return nullptr;
    const toml::array* a = n->as_array();
    if (!a || !a->is_array_of_tables())
      throw InputError(full(key) + " = " + shown_value(*n) + ": expected entries [[" + full(key) +
                       "]] with " + keys_of_table(schema_ + "." + key));
    return a;
  }
  // Throws for the first key of the table that no reader asked for.
  void finish() const {
    if (!table_) return;
    for (const auto& [k, v] : *table_) {
      const std::string key(k.str());
      if (std::find(used_.begin(), used_.end(), key) == used_.end())
        unknown_key(schema_ + "." + key, shown_ + "." + key);
    }
  }

 private:
  const KeySpec& spec(const char* key) const {
    const KeySpec* s = find_spec(schema_ + "." + key);
    if (!s) throw std::logic_error("case_file: key missing from schema: " + schema_ + "." + key);
    return *s;
  }
  const toml::table* table_;
  std::string shown_;
  std::string schema_;
  std::vector<std::string> used_;
};

std::string fmt_si(double v, Dimension dim) {
  return format_number(v) + (si_unit(dim).empty() ? "" : " " + std::string(si_unit(dim)));
}

void require(bool ok, const std::string& key, double v, Dimension dim, const std::string& allowed) {
  if (!ok) throw InputError(key + " = " + fmt_si(v, dim) + ": " + allowed);
}

// Applies the material keys of one table to each of the given materials.
void read_material(TableReader& r, std::initializer_list<Material*> targets) {
  const auto young = r.quantity("young");
  const auto poisson = r.quantity("poisson");
  const auto density = r.quantity("density");
  for (Material* m : targets) {
    if (young) m->young = *young;
    if (poisson) m->poisson = *poisson;
    if (density) m->density = *density;
  }
}

const toml::table* top_table(const toml::table& doc, const char* name) {
  const toml::node* n = doc.get(name);
  if (!n) return nullptr;
  if (!n->is_table())
    throw InputError(std::string(name) + " = " + shown_value(*n) + ": expected a table [" + name +
                     "] with " + keys_of_table(name) + ", got " + type_name(*n));
  return n->as_table();
}

std::string join_path(const std::string& base_dir, const std::string& path) {
  if (base_dir.empty() || path.empty() || path.front() == '/') return path;
  return base_dir + "/" + path;
}

std::vector<WavinessHarmonic> read_waviness(TableReader& parent, const char* race, const Bearing& b,
                                            const std::string& base_dir) {
  std::vector<WavinessHarmonic> out;
  const toml::array* entries = parent.table_array(race);
  if (!entries) return out;
  const std::string schema = std::string("waviness.") + race;
  for (std::size_t i = 0; i < entries->size(); ++i) {
    const std::string shown = schema + "[" + std::to_string(i) + "]";
    TableReader r(entries->get(i)->as_table(), shown, schema);
    if (auto table = r.text("table")) {
      for (const char* k : {"order", "amplitude", "phase"})
        if (r.has(k))
          throw InputError(r.full(k) +
                           ": give either table = \"file.csv\" or order/amplitude/"
                           "phase in one [[" +
                           schema + "]] entry, not both");
      const auto rows = read_waviness_table(join_path(base_dir, *table), r.full("table"));
      out.insert(out.end(), rows.begin(), rows.end());
    } else {
      WavinessHarmonic h;
      const auto order = r.integer("order");
      const auto amplitude = r.quantity("amplitude");
      if (!order || !amplitude)
        throw InputError(shown +
                         ": each entry needs order and amplitude (phase optional), or "
                         "table = \"file.csv\"");
      if (*order < 1 || *order > 100000)
        throw InputError(r.full("order") + " = " + std::to_string(*order) +
                         ": waves per revolution must be an integer >= 1");
      h.order = static_cast<int>(*order);
      h.amplitude = *amplitude;
      h.phase = r.quantity("phase").value_or(0.0);
      out.push_back(h);
    }
    r.finish();
  }
  for (std::size_t i = 0; i < out.size(); ++i) {
    const std::string key = schema + "[" + std::to_string(i) + "].amplitude";
    require(std::isfinite(out[i].amplitude) && out[i].amplitude >= 0 &&
                out[i].amplitude < 0.01 * b.ball_diameter,
            key, out[i].amplitude, Dimension::length,
            "must be >= 0 and below 1 % of the ball diameter (waviness is a few um at most)");
  }
  return out;
}

Case resolve(const toml::table& doc, const std::string& source, const std::string& base_dir) {
  for (const auto& [k, v] : doc) {
    const std::string key(k.str());
    if (std::find(top_tables().begin(), top_tables().end(), key) == top_tables().end())
      unknown_key(key, key);
  }
  Case c;
  c.source = source;

  // [bearing]
  TableReader bearing(top_table(doc, "bearing"), "bearing");
  if (auto p = bearing.text("preset", /*allow_integer=*/true)) {
    c.preset = *p;
    c.bearing = preset(*p);
  } else {
    c.bearing.designation = "custom";
  }
  Bearing& b = c.bearing;
  const auto required = [&](const char* key) {
    if (c.preset.empty())
      throw InputError("bearing." + std::string(key) +
                       " is missing: give it, or choose a catalogue bearing with bearing.preset (" +
                       "608, 6304, 6308, 6205, 209)");
  };
  if (auto v = bearing.quantity("ball_diameter"))
    b.ball_diameter = *v;
  else
    required("ball_diameter");
  if (auto v = bearing.quantity("pitch_diameter"))
    b.pitch_diameter = *v;
  else
    required("pitch_diameter");
  if (auto v = bearing.integer("balls")) {
    if (*v < 3 || *v > 1000000)
      throw InputError("bearing.balls = " + std::to_string(*v) +
                       ": a radial ball bearing needs at least 3 balls (allowed: integer >= 3)");
    b.balls = static_cast<int>(*v);
  } else {
    required("balls");
  }
  if (auto v = bearing.quantity("inner_conformity"))
    b.inner_conformity = *v;
  else
    required("inner_conformity");
  if (auto v = bearing.quantity("outer_conformity"))
    b.outer_conformity = *v;
  else
    required("outer_conformity");
  if (auto v = bearing.quantity("clearance"))
    b.clearance = *v;
  else
    required("clearance");
  if (auto v = bearing.quantity("contact_angle")) b.contact_angle = *v;
  bearing.finish();

  // [material], [material.ball], [material.rings]
  TableReader material(top_table(doc, "material"), "material");
  read_material(material, {&b.ball, &b.rings});
  TableReader ball(material.subtable("ball"), "material.ball");
  read_material(ball, {&b.ball});
  ball.finish();
  TableReader rings(material.subtable("rings"), "material.rings");
  read_material(rings, {&b.rings});
  rings.finish();
  material.finish();
  b.validate();

  // [rotor]
  TableReader rotor(top_table(doc, "rotor"), "rotor");
  if (auto v = rotor.quantity("mass")) c.rotor.mass = *v;
  if (auto v = rotor.quantity("damping")) c.rotor.damping = *v;
  c.rotor.axial_mass = rotor.quantity("axial_mass").value_or(c.rotor.mass);
  c.rotor.axial_damping = rotor.quantity("axial_damping").value_or(c.rotor.damping);
  rotor.finish();
  require(c.rotor.mass > 0, "rotor.mass", c.rotor.mass, Dimension::mass,
          "must be positive (> 0 kg)");
  require(c.rotor.damping >= 0, "rotor.damping", c.rotor.damping, Dimension::damping,
          "must be >= 0");
  require(c.rotor.axial_mass > 0, "rotor.axial_mass", c.rotor.axial_mass, Dimension::mass,
          "must be positive (> 0 kg)");
  require(c.rotor.axial_damping >= 0, "rotor.axial_damping", c.rotor.axial_damping,
          Dimension::damping, "must be >= 0");

  // [operation]
  TableReader operation(top_table(doc, "operation"), "operation");
  if (auto v = operation.quantity("speed")) c.operation.speed = *v;
  if (auto v = operation.vector2("load")) c.operation.load = *v;
  if (auto v = operation.quantity("axial_load")) c.operation.axial_load = *v;
  if (auto v = operation.quantity("unbalance")) c.operation.unbalance = *v;
  if (auto v = operation.boolean("gravity")) c.operation.gravity = *v;
  operation.finish();
  if (!(c.operation.speed >= 0))
    throw InputError(
        "operation.speed = " + format_quantity(c.operation.speed, "rpm", Dimension::angular_speed) +
        ": must be >= 0 rpm (the inner ring turns counter-clockwise seen from +z)");
  require(c.operation.unbalance >= 0, "operation.unbalance", c.operation.unbalance,
          Dimension::mass_length, "must be >= 0");

  // [waviness], [ball_errors]
  TableReader waviness(top_table(doc, "waviness"), "waviness");
  c.excitation.inner_waviness = read_waviness(waviness, "inner", b, base_dir);
  c.excitation.outer_waviness = read_waviness(waviness, "outer", b, base_dir);
  waviness.finish();

  TableReader errors(top_table(doc, "ball_errors"), "ball_errors");
  const auto values = errors.list("values");
  const auto band = errors.quantity("band");
  const auto seed = errors.integer("seed");
  errors.finish();
  if (values && band)
    throw InputError("ball_errors: give either values (one per ball) or band (+ seed), not both");
  if (seed && !band)
    throw InputError("ball_errors.seed = " + std::to_string(*seed) +
                     ": a seed needs ball_errors.band to draw from");
  if (values) {
    if (static_cast<int>(values->size()) != b.balls)
      throw InputError("ball_errors.values has " + std::to_string(values->size()) +
                       " entries: expected one per ball (" + std::to_string(b.balls) + ")");
    for (std::size_t j = 0; j < values->size(); ++j) {
      require(std::fabs((*values)[j]) < 0.01 * b.ball_diameter,
              "ball_errors.values[" + std::to_string(j) + "]", (*values)[j], Dimension::length,
              "a ball-size error must be below 1 % of the ball diameter");
      c.excitation.ball_size_errors.push_back(-(*values)[j]);  // ΔD_j = D − D_j
    }
  }
  if (band) {
    require(*band >= 0 && *band < 0.02 * b.ball_diameter, "ball_errors.band", *band,
            Dimension::length, "must be >= 0 and below 2 % of the ball diameter");
    if (seed && *seed < 0)
      throw InputError("ball_errors.seed = " + std::to_string(*seed) + ": must be >= 0");
    c.excitation.ball_error_band = *band;
    c.excitation.ball_error_seed = seed ? static_cast<std::uint64_t>(*seed) : 1u;
    c.excitation.ball_size_errors =
        ball_size_errors_from_band(b.balls, *band, c.excitation.ball_error_seed);
  }

  // [model]
  TableReader model(top_table(doc, "model"), "model");
  if (auto v = model.text("kind")) {
    if (*v != "2dof" && *v != "3dof" && *v != "balls" && *v != "quasistatic")
      throw InputError("model.kind = \"" + *v +
                       "\": unknown model; allowed: 2dof, 3dof, balls, quasistatic");
    c.model.kind = *v;
  }
  if (auto v = model.text("contact")) {
    if (*v != "calibrated") {
      try {
        make_hertz_solution(*v, "model.contact");  // throws for an unknown name
      } catch (const InputError& e) {
        if (detail::edit_distance(*v, "calibrated") <= 3)
          throw InputError("model.contact = \"" + *v +
                           "\": unknown contact law (did you mean \"calibrated\"?); allowed: "
                           "\"exact\", \"hamrock-brewe\", \"harris-table\", \"calibrated\"");
        throw InputError(std::string(e.what()) +
                         "; or \"calibrated\" (FE constants, with model.calibration)");
      }
    }
    c.model.contact = *v;
  }
  // The FE constants: found relative to the case file, checked against the bearing now, so a
  // calibration for another bearing never reaches a model. An empty string means none (so that
  // `--set 'model.calibration=""'` can switch a calibrated case back to a Hertz method).
  const auto calibration = model.text("calibration");
  const bool calibrated = c.model.contact == "calibrated";
  if (calibration && !calibration->empty()) {
    const std::string shown = "model.calibration = \"" + *calibration + "\"";
    if (!calibrated)
      throw InputError(shown +
                       ": a calibration file is only used with model.contact = "
                       "\"calibrated\" (the case has model.contact = \"" +
                       c.model.contact + "\"); set both, or remove model.calibration");
    c.model.calibration = read_calibration(join_path(base_dir, *calibration), shown);
    check_calibration_bearing(*c.model.calibration, b, shown);
  } else if (calibrated) {
    throw InputError(
        "model.contact = \"calibrated\" needs model.calibration = \"calibration.json\", the FE "
        "constants written by bearing-fem calibrate for this bearing (a path relative to the case "
        "file)");
  }
  if (auto v = model.boolean("waviness_stiffness")) c.model.waviness_stiffness = *v;
  model.finish();

  // [cage], [ball]: the ball-DOF model's; an error with any other model, which would ignore them.
  const bool balls = c.model.kind == "balls";
  const auto only_balls = [&](const char* table) {
    if (!balls && top_table(doc, table))
      throw InputError(std::string("[") + table + "] is used by model.kind = \"balls\" only (the " +
                       "case has model.kind = \"" + c.model.kind + "\"): remove it or set kind");
  };
  only_balls("cage");
  only_balls("ball");
  TableReader cage(top_table(doc, "cage"), "cage");
  if (auto v = cage.quantity("slip")) c.cage.slip = *v;
  if (auto v = cage.quantity("friction")) c.cage.friction = *v;
  if (auto v = cage.quantity("slide_speed")) c.cage.slide_speed = *v;
  cage.finish();
  require(c.cage.slip >= 0 && c.cage.slip < 1, "cage.slip", c.cage.slip, Dimension::dimensionless,
          "must lie in [0, 1) (0: pure rolling; 0.02: 2 %)");
  require(c.cage.friction >= 0 && c.cage.friction <= 1, "cage.friction", c.cage.friction,
          Dimension::dimensionless, "must lie in [0, 1] (0: no friction)");
  require(c.cage.slide_speed > 0 && c.cage.slide_speed <= 100, "cage.slide_speed",
          c.cage.slide_speed, Dimension::velocity, "must lie in (0, 100 m/s]");
  TableReader ball_table(top_table(doc, "ball"), "ball");
  const double D = b.ball_diameter, pi = 3.14159265358979323846;
  c.ball.mass = ball_table.quantity("mass").value_or(b.ball.density * pi * D * D * D / 6.0);
  c.ball.inertia = ball_table.quantity("inertia").value_or(c.ball.mass * D * D / 10.0);
  c.ball.damping = ball_table.quantity("damping").value_or(c.rotor.damping);
  if (auto v = ball_table.boolean("centrifugal")) c.ball.centrifugal = *v;
  ball_table.finish();
  require(c.ball.mass > 0, "ball.mass", c.ball.mass, Dimension::mass, "must be positive");
  require(c.ball.inertia > 0, "ball.inertia", c.ball.inertia, Dimension::inertia,
          "must be positive");
  require(c.ball.damping >= 0, "ball.damping", c.ball.damping, Dimension::damping, "must be >= 0");

  // [solver]
  TableReader solver(top_table(doc, "solver"), "solver");
  SolverOptions& s = c.solver;
  if (auto v = solver.choice("method", {"rk4", "rkf45", "rk8pd", "newmark", "bdf"})) s.method = *v;
  if (auto v = solver.quantity("dt")) s.dt = *v;
  if (auto v = solver.quantity("duration")) s.duration = *v;
  if (auto v = solver.quantity("transient")) s.transient = *v;
  if (auto v = solver.quantity("tolerance")) s.tolerance = *v;
  if (auto v = solver.quantity("output_rate")) s.output_rate = *v;
  if (auto v = solver.quantity("max_displacement")) s.max_displacement = *v;
  solver.finish();
  require(s.dt > 0 && s.dt <= 1e-3, "solver.dt", s.dt, Dimension::time,
          "must lie in (0, 1 ms]; the Hertz contacts need a few us");
  require(s.duration > 0 && s.duration <= 1000, "solver.duration", s.duration, Dimension::time,
          "must lie in (0, 1000 s]");
  require(s.transient >= 0 && s.transient < s.duration, "solver.transient", s.transient,
          Dimension::time,
          "must be >= 0 and shorter than solver.duration (" + fmt_si(s.duration, Dimension::time) +
              ")");
  require(s.tolerance > 0 && s.tolerance <= 0.1, "solver.tolerance", s.tolerance,
          Dimension::dimensionless, "must lie in (0, 0.1]");
  require(s.output_rate > 0 && s.output_rate <= 1e7, "solver.output_rate", s.output_rate,
          Dimension::frequency, "must lie in (0, 10 MHz]");
  const double samples = s.output_rate * s.duration;
  require(samples <= 2e7, "solver.output_rate", s.output_rate, Dimension::frequency,
          "gives " + format_number(samples) + " samples over solver.duration; at most 2e7");
  require((s.duration - s.transient) * s.output_rate >= 16, "solver.output_rate", s.output_rate,
          Dimension::frequency,
          "gives fewer than 16 samples after the transient: raise it or solver.duration");
  require(s.max_displacement > 0, "solver.max_displacement", s.max_displacement, Dimension::length,
          "must be positive");

  // [output]
  TableReader output(top_table(doc, "output"), "output");
  if (auto v = output.boolean("ball_loads")) c.output.ball_loads = *v;
  if (auto v = output.boolean("ball_motion")) c.output.ball_motion = *v;
  if (auto v = output.boolean("ball_approach")) c.output.ball_approach = *v;
  if (auto v = output.boolean("ball_dynamics")) c.output.ball_dynamics = *v;
  if (c.output.ball_dynamics && !balls)
    throw InputError(
        "output.ball_dynamics = true: the spin, outer load and friction channels "
        "need model.kind = \"balls\" (the case has \"" +
        c.model.kind + "\")");
  if (auto v = output.choice("window", {"hann", "flattop", "rectangular"})) c.output.window = *v;
  if (auto v = output.integer("peaks")) {
    if (*v < 0 || *v > 1000)
      throw InputError("output.peaks = " + std::to_string(*v) + ": allowed 0 to 1000");
    c.output.peaks = static_cast<int>(*v);
  }
  output.finish();

  // [acoustics]: its presence turns the sound-pressure outputs on.
  const toml::table* acoustics_table = top_table(doc, "acoustics");
  TableReader acoustics(acoustics_table, "acoustics");
  AcousticsOptions& ac = c.acoustics;
  ac.enabled = acoustics_table != nullptr;
  ac.ring_radius = 0.5 * b.inner_raceway_diameter();
  if (auto v = acoustics.choice("ring_source", {"cylinder-dipole", "paper", "none"}))
    ac.ring_source = *v;
  if (auto v = acoustics.choice("ball_source",
                                {"oscillating-sphere", "pulsating-sphere", "paper", "none"}))
    ac.ball_source = *v;
  if (auto v = acoustics.choice("summation", {"coherent", "energetic"})) ac.summation = *v;
  if (auto v = acoustics.points("microphones")) ac.microphones = *v;
  if (auto v = acoustics.quantity("ring_radius")) ac.ring_radius = *v;
  if (auto v = acoustics.quantity("density")) ac.density = *v;
  if (auto v = acoustics.quantity("sound_speed")) ac.sound_speed = *v;
  acoustics.finish();
  if (ac.enabled) {
    if (ac.microphones.empty())
      throw InputError(
          "acoustics.microphones is missing or empty: an [acoustics] table needs at least one "
          "microphone [r, angle] in the bearing plane, e.g. microphones = [[\"10 mm\", \"-90 "
          "deg\"]]");
    for (std::size_t i = 0; i < ac.microphones.size(); ++i) {
      const double r = ac.microphones[i].radius;
      require(r > 0 && r <= 100.0, "acoustics.microphones[" + std::to_string(i) + "] r", r,
              Dimension::length, "must lie in (0, 100 m]");
    }
    require(ac.ring_radius > 0 && ac.ring_radius < 0.5 * b.pitch_diameter, "acoustics.ring_radius",
            ac.ring_radius, Dimension::length,
            "must lie in (0, d_m/2 = " + fmt_si(0.5 * b.pitch_diameter, Dimension::length) + ")");
    require(ac.density > 0 && ac.density <= 2e4, "acoustics.density", ac.density,
            Dimension::density, "must lie in (0, 20000 kg/m^3]");
    require(ac.sound_speed > 0 && ac.sound_speed <= 1e4, "acoustics.sound_speed", ac.sound_speed,
            Dimension::velocity, "must lie in (0, 10000 m/s]");
    // A microphone must lie outside every source: outside the ring, and outside the annulus the
    // balls sweep (its radii move by the micrometres of the run; bearing_noise checks again).
    const double swept_in = 0.5 * (b.pitch_diameter - b.ball_diameter);
    const double swept_out = 0.5 * (b.pitch_diameter + b.ball_diameter);
    for (std::size_t i = 0; i < ac.microphones.size(); ++i) {
      const double r = ac.microphones[i].radius;
      const std::string key = "acoustics.microphones[" + std::to_string(i) + "] r";
      if (ac.ring_source != "none")
        require(r > ac.ring_radius, key, r, Dimension::length,
                "inside the ring source (acoustics.ring_radius = " +
                    fmt_si(ac.ring_radius, Dimension::length) +
                    "): a microphone must lie outside it");
      if (ac.ball_source != "none")
        require(r < swept_in || r > swept_out, key, r, Dimension::length,
                "inside the annulus the balls sweep, " + fmt_si(swept_in, Dimension::length) +
                    " … " + fmt_si(swept_out, Dimension::length) +
                    " ((d_m ∓ D)/2): a ball would pass through the microphone; move it, or set "
                    "acoustics.ball_source = \"none\"");
    }
    if (ac.ring_source == "none" && ac.ball_source == "none")
      throw InputError(
          "acoustics: ring_source and ball_source are both \"none\": nothing radiates; choose a "
          "source or remove the [acoustics] table");
  }
  return c;
}

// Parses an override value as TOML; anything that is not valid TOML is taken as a string.
toml::table override_value(const std::string& value) {
  try {
    return toml::parse("v = " + value);
  } catch (const toml::parse_error&) {
    toml::table t;
    t.insert("v", value);
    return t;
  }
}

bool is_index(const std::string& part) {
  return !part.empty() && std::all_of(part.begin(), part.end(), ::isdigit);
}

void apply_override(toml::table& doc, const Override& o) {
  std::vector<std::string> parts;
  std::stringstream ss(o.key);
  for (std::string p; std::getline(ss, p, '.');) parts.push_back(p);
  const std::string where = "--set " + o.key + "=" + o.value + ": ";
  toml::node* node = &doc;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    if (toml::array* a = node->as_array(); a && is_index(parts[i])) {
      const std::size_t index = std::stoul(parts[i]);
      if (index >= a->size())
        throw InputError(where + "index " + parts[i] + " is past the " + std::to_string(a->size()) +
                         " entries of " + parts[i - 1]);
      node = a->get(index);
      continue;
    }
    toml::table* t = node->as_table();
    if (!t) throw InputError(where + "\"" + parts[i - 1] + "\" is a value, not a table");
    if (!t->get(parts[i])) t->insert(parts[i], toml::table{});
    node = t->get(parts[i]);
    if (!node->is_table() && !node->is_array())
      throw InputError(where + "\"" + parts[i] + "\" is a value, not a table");
  }
  toml::table* t = node->as_table();
  if (!t) throw InputError(where + "\"" + parts[parts.size() - 2] + "\" is not a table");
  toml::table parsed = override_value(o.value);
  t->insert_or_assign(parts.back(), std::move(*parsed.get("v")));
  // A file named on the command line is relative to the working directory, not to the case
  // file's folder: make it absolute here, before the case resolves relative paths.
  if (o.key == "model.calibration")
    if (auto* path = t->get(parts.back())->as_string();
        path && !path->get().empty() && path->get().front() != '/')
      *path = std::filesystem::absolute(path->get()).lexically_normal().string();
}

std::string schema_name(const std::string& key) {
  // "waviness.inner.0.amplitude" → "waviness.inner.amplitude"
  std::stringstream ss(key);
  std::string out;
  for (std::string p; std::getline(ss, p, '.');)
    if (!is_index(p)) out += (out.empty() ? "" : ".") + p;
  return out;
}

}  // namespace

Override parse_override(std::string_view text) {
  const auto eq = text.find('=');
  const std::string t(text);
  if (eq == std::string_view::npos)
    throw InputError("--set " + t +
                     ": expected table.key=value, e.g. --set operation.speed=3000rpm");
  Override o{std::string(text.substr(0, eq)), std::string(text.substr(eq + 1))};
  const bool dotted = o.key.find('.') != std::string::npos && o.key.front() != '.' &&
                      o.key.back() != '.' && o.key.find("..") == std::string::npos &&
                      !is_index(o.key.substr(0, o.key.find('.')));
  if (!dotted) throw InputError("--set " + t + ": the key must be table.key, e.g. bearing.balls=9");
  if (o.value.empty()) throw InputError("--set " + t + ": no value after '='");
  return o;
}

Case parse_case(std::string_view toml_text, const std::string& source,
                const std::vector<Override>& overrides, const std::string& base_dir) {
  toml::table doc;
  try {
    doc = toml::parse(toml_text, source);
  } catch (const toml::parse_error& e) {
    const auto& where = e.source().begin;
    throw InputError(source + ":" + std::to_string(where.line) + ":" +
                     std::to_string(where.column) +
                     ": TOML syntax error: " + std::string(e.description()));
  }
  try {
    for (const auto& o : overrides) apply_override(doc, o);
    return resolve(doc, source, base_dir);
  } catch (const InputError& e) {
    throw InputError(source + ": " + e.what());
  }
}

Case read_case_file(const std::string& path, const std::vector<Override>& overrides) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot read the case file (" + std::strerror(errno) + ")");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path + ": cannot read the case file");
  const auto slash = path.rfind('/');
  return parse_case(text.str(), path, overrides,
                    slash == std::string::npos ? std::string() : path.substr(0, slash));
}

std::string_view default_case_toml() {
  return R"(# Built-in default case: the 6308 of seed 003 (Table 1) at its 2000 rpm, under the 20 N
# radial load seed 002 applies to the same bearing, pointing down (y is up).
[bearing]
preset = "6308"

[operation]
speed = "2000 rpm"
load = ["0 N", "-20 N"]
)";
}

Case default_case(const std::vector<Override>& overrides) {
  return parse_case(default_case_toml(), "built-in default case", overrides);
}

namespace {

std::string num17(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  std::string s = buf;
  // TOML needs a float to look like one.
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char ch : s) {
    if (ch == '"' || ch == '\\') out += '\\';
    out += ch;
  }
  return out + "\"";
}

}  // namespace

std::string case_to_toml(const Case& c) {
  const Bearing& b = c.bearing;
  std::ostringstream o;
  o << "# Fully resolved case (SI units: m, kg, s, N, Pa, rad, rad/s, Hz), written by "
       "bearing-sim.\n"
    << "# Source: " << c.source << (c.preset.empty() ? "" : ", preset " + c.preset) << "\n\n";
  o << "[bearing]\n";
  o << "ball_diameter = " << num17(b.ball_diameter) << "\n";
  o << "pitch_diameter = " << num17(b.pitch_diameter) << "\n";
  o << "balls = " << b.balls << "\n";
  o << "inner_conformity = " << num17(b.inner_conformity) << "\n";
  o << "outer_conformity = " << num17(b.outer_conformity) << "\n";
  o << "clearance = " << num17(b.clearance) << "\n";
  o << "contact_angle = \"" << num17(b.contact_angle) << " rad\"\n\n";
  for (const auto& [name, m] : {std::pair{"ball", &b.ball}, std::pair{"rings", &b.rings}})
    o << "[material." << name << "]\nyoung = " << num17(m->young)
      << "\npoisson = " << num17(m->poisson) << "\ndensity = " << num17(m->density) << "\n\n";
  o << "[rotor]\nmass = " << num17(c.rotor.mass) << "\ndamping = " << num17(c.rotor.damping)
    << "\naxial_mass = " << num17(c.rotor.axial_mass)
    << "\naxial_damping = " << num17(c.rotor.axial_damping) << "\n\n";
  o << "[operation]\nspeed = \"" << num17(c.operation.speed) << " rad/s\"\nload = ["
    << num17(c.operation.load.x()) << ", " << num17(c.operation.load.y()) << "]\n"
    << "axial_load = " << num17(c.operation.axial_load)
    << "\nunbalance = " << num17(c.operation.unbalance)
    << "\ngravity = " << (c.operation.gravity ? "true" : "false") << "\n\n";
  for (const auto& [race, list] : {std::pair{"inner", &c.excitation.inner_waviness},
                                   std::pair{"outer", &c.excitation.outer_waviness}})
    for (const auto& h : *list)
      o << "[[waviness." << race << "]]\norder = " << h.order
        << "\namplitude = " << num17(h.amplitude) << "\nphase = \"" << num17(h.phase)
        << " rad\"\n\n";
  if (!c.excitation.ball_size_errors.empty()) {
    o << "[ball_errors]\n";
    if (c.excitation.ball_error_band > 0)
      o << "# drawn from band " << num17(c.excitation.ball_error_band) << " m with seed "
        << c.excitation.ball_error_seed << "\n";
    o << "values = [";  // D_j − D = −ΔD_j
    for (std::size_t j = 0; j < c.excitation.ball_size_errors.size(); ++j)
      o << (j ? ", " : "") << num17(-c.excitation.ball_size_errors[j]);
    o << "]\n\n";
  }
  o << "[model]\nkind = " << quoted(c.model.kind) << "\ncontact = " << quoted(c.model.contact);
  if (c.model.calibration) o << "\ncalibration = " << quoted(c.model.calibration->path);
  o << "\nwaviness_stiffness = " << (c.model.waviness_stiffness ? "true" : "false") << "\n\n";
  if (c.model.kind == "balls") {
    o << "[cage]\nslip = " << num17(c.cage.slip) << "\nfriction = " << num17(c.cage.friction)
      << "\nslide_speed = " << num17(c.cage.slide_speed) << "\n\n";
    o << "[ball]\nmass = " << num17(c.ball.mass) << "\ninertia = " << num17(c.ball.inertia)
      << "\ndamping = " << num17(c.ball.damping)
      << "\ncentrifugal = " << (c.ball.centrifugal ? "true" : "false") << "\n\n";
  }
  const SolverOptions& s = c.solver;
  o << "[solver]\nmethod = " << quoted(s.method) << "\ndt = " << num17(s.dt)
    << "\nduration = " << num17(s.duration) << "\ntransient = " << num17(s.transient)
    << "\ntolerance = " << num17(s.tolerance) << "\noutput_rate = " << num17(s.output_rate)
    << "\nmax_displacement = " << num17(s.max_displacement) << "\n\n";
  o << "[output]\nball_loads = " << (c.output.ball_loads ? "true" : "false")
    << "\nball_motion = " << (c.output.ball_motion ? "true" : "false")
    << "\nball_approach = " << (c.output.ball_approach ? "true" : "false")
    << "\nball_dynamics = " << (c.output.ball_dynamics ? "true" : "false")
    << "\nwindow = " << quoted(c.output.window) << "\npeaks = " << c.output.peaks << "\n";
  const AcousticsOptions& ac = c.acoustics;
  if (ac.enabled) {
    o << "\n[acoustics]\nring_source = " << quoted(ac.ring_source)
      << "\nball_source = " << quoted(ac.ball_source) << "\nsummation = " << quoted(ac.summation)
      << "\nmicrophones = [";
    for (std::size_t i = 0; i < ac.microphones.size(); ++i)
      o << (i ? ", " : "") << "[" << num17(ac.microphones[i].radius) << ", \""
        << num17(ac.microphones[i].angle) << " rad\"]";
    o << "]\nring_radius = " << num17(ac.ring_radius) << "\ndensity = " << num17(ac.density)
      << "\nsound_speed = " << num17(ac.sound_speed) << "\n";
  }
  return o.str();
}

ContactConstants contact_constants(const Case& c) {
  if (c.model.contact == "calibrated") {
    if (!c.model.calibration)
      throw InputError("model.contact = \"calibrated\" needs model.calibration");
    return calibrated_contact_constants(c.bearing, *c.model.calibration);
  }
  return contact_constants(c.bearing, *make_hertz_solution(c.model.contact));
}

std::string hertz_shape_method(const ModelOptions& m) {
  return m.contact == "calibrated" ? "exact" : m.contact;
}

Dimension key_dimension(const std::string& key) {
  const KeySpec* s = find_spec(schema_name(key));
  if (!s || !(s->kind == Kind::quantity || s->kind == Kind::integer))
    throw InputError(key + ": not a numeric case-file key (see bearing-sim run --help)");
  return s->dim;
}

bool key_is_integer(const std::string& key) {
  const KeySpec* s = find_spec(schema_name(key));
  return s && s->kind == Kind::integer;
}

std::string case_keys_help() {
  std::string out;
  for (const auto& k : schema()) {
    if (k.kind == Kind::table) continue;
    std::string units;
    if (k.kind == Kind::integer || k.kind == Kind::text || k.kind == Kind::boolean ||
        k.kind == Kind::table_array || k.dim == Dimension::dimensionless) {
      units = k.kind == Kind::text          ? "text"
              : k.kind == Kind::boolean     ? "true/false"
              : k.kind == Kind::table_array ? "entries"
                                            : "number";
    } else if (k.kind == Kind::points) {
      units = "pairs of a length and an angle (deg or rad)";
    } else {
      units = (bare_number_is_si(k.dim) ? std::string(si_unit(k.dim)) + " if plain; "
                                        : "unit required; ") +
              join(accepted_units(k.dim));
    }
    std::string name = k.name;
    name.resize(std::max<std::size_t>(name.size() + 1, 30), ' ');
    out += "  " + name + k.help + " [" + units + "]\n";
  }
  return out;
}

std::vector<std::string> known_keys() {
  std::vector<std::string> out;
  for (const auto& k : schema())
    if (k.kind != Kind::table) out.push_back(k.name);
  return out;
}

}  // namespace bearing
