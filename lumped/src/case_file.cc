#include "bearing/case_file.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include <toml++/toml.h>

#include "bearing/errors.h"
#include "bearing/hertz.h"
#include "bearing/presets.h"
#include "bearing/units.h"
#include "edit_distance.h"

namespace bearing {

namespace {

// ---------------------------------------------------------------------------------------------
// The schema: every key the reader accepts, with its dimension. The readers below ask for keys by
// these names; unknown keys are what is left over.
// ---------------------------------------------------------------------------------------------
enum class Kind { quantity, integer, text, vector2, table };

struct KeySpec {
  const char* name;  // "bearing.ball_diameter"
  Kind kind;
  Dimension dim;
  const char* help;
};

const std::vector<KeySpec>& schema() {
  static const std::vector<KeySpec> keys{
      {"bearing.preset", Kind::text, Dimension::dimensionless,
       "catalogue bearing (608, 6304, 6308, 6205, 209); other keys override it"},
      {"bearing.ball_diameter", Kind::quantity, Dimension::length, "ball diameter D"},
      {"bearing.pitch_diameter", Kind::quantity, Dimension::length, "pitch diameter d_m"},
      {"bearing.balls", Kind::integer, Dimension::dimensionless, "number of balls Z (>= 3)"},
      {"bearing.inner_conformity", Kind::quantity, Dimension::dimensionless,
       "inner groove radius / D (> 0.5)"},
      {"bearing.outer_conformity", Kind::quantity, Dimension::dimensionless,
       "outer groove radius / D (> 0.5)"},
      {"bearing.clearance", Kind::quantity, Dimension::length,
       "ISO radial internal clearance P_d (diametral); each ball's gap is P_d/2"},
      {"bearing.contact_angle", Kind::quantity, Dimension::angle, "free contact angle alpha"},
      {"material.young", Kind::quantity, Dimension::pressure, "Young's modulus, balls and rings"},
      {"material.poisson", Kind::quantity, Dimension::dimensionless, "Poisson ratio in (-1, 0.5)"},
      {"material.density", Kind::quantity, Dimension::density, "density"},
      {"material.ball", Kind::table, Dimension::dimensionless,
       "ball material (young, poisson, density)"},
      {"material.rings", Kind::table, Dimension::dimensionless,
       "ring material (young, poisson, density)"},
      {"material.ball.young", Kind::quantity, Dimension::pressure, "ball Young's modulus"},
      {"material.ball.poisson", Kind::quantity, Dimension::dimensionless, "ball Poisson ratio"},
      {"material.ball.density", Kind::quantity, Dimension::density, "ball density"},
      {"material.rings.young", Kind::quantity, Dimension::pressure, "ring Young's modulus"},
      {"material.rings.poisson", Kind::quantity, Dimension::dimensionless, "ring Poisson ratio"},
      {"material.rings.density", Kind::quantity, Dimension::density, "ring density"},
      {"operation.speed", Kind::quantity, Dimension::angular_speed, "inner-ring speed"},
      {"operation.load", Kind::vector2, Dimension::force,
       "radial load [Fx, Fy] on the inner ring (y up: Fy < 0 pushes down)"},
      {"model.contact", Kind::text, Dimension::dimensionless,
       "Hertz method: exact | hamrock-brewe | harris-table"},
  };
  return keys;
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
// closest spelling in the same table.
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

[[noreturn]] void unknown_key(const std::string& name) {
  const auto dot = name.rfind('.');
  const std::string table = dot == std::string::npos ? std::string() : name.substr(0, dot);
  std::string msg;
  if (table.empty() || !(find_spec(table) || !keys_of_table(table).empty())) {
    msg = "unknown table or key \"" + name + "\"";
    const std::string s = suggestion(name);
    if (!s.empty()) msg += "; did you mean \"" + s + "\"?";
    msg +=
        " Known tables: [bearing], [material] (with [material.ball], [material.rings]), "
        "[operation], [model]";
  } else {
    msg = "unknown key \"" + name + "\"";
    const std::string s = suggestion(name);
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

// A quantity: a plain number (SI) or a string with a unit.
double read_quantity(const toml::node& node, const std::string& key, Dimension dim) {
  if (node.is_integer() || node.is_floating_point()) {
    const double v = node.value<double>().value();
    if (!std::isfinite(v))
      throw InputError(key + " = " + shown_value(node) + ": must be a finite number");
    if (dim != Dimension::dimensionless && !bare_number_is_si(dim) && v != 0.0) {
      std::string units;
      for (const auto& u : accepted_units(dim)) units += (units.empty() ? "" : ", ") + u;
      throw InputError(key + " = " + shown_value(node) + ": missing unit; an " +
                       std::string(dimension_name(dim)) +
                       " needs one because a bare number is ambiguous, e.g. \"" +
                       shown_value(node) + " " + accepted_units(dim).front() +
                       "\" (accepted units: " + units + ")");
    }
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
  TableReader(const toml::table* table, std::string name) : table_(table), name_(std::move(name)) {}

  const toml::node* get(const char* key) {
    used_.push_back(key);
    return table_ ? table_->get(key) : nullptr;
  }
  std::string full(const char* key) const { return name_ + "." + key; }

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
  const toml::table* subtable(const char* key) {
    const toml::node* n = get(key);
    if (!n) return nullptr;
    if (!n->is_table())
      throw InputError(full(key) + " = " + shown_value(*n) + ": expected a table [" + full(key) +
                       "] with " + keys_of_table(full(key)) + ", got " + type_name(*n));
    return n->as_table();
  }
  // Throws for the first key of the table that no reader asked for.
  void finish() const {
    if (!table_) return;
    for (const auto& [k, v] : *table_) {
      const std::string key(k.str());
      if (std::find(used_.begin(), used_.end(), key) == used_.end()) unknown_key(name_ + "." + key);
    }
  }

 private:
  const KeySpec& spec(const char* key) const {
    const KeySpec* s = find_spec(full(key));
    if (!s) throw std::logic_error("case_file: key missing from schema: " + full(key));
    return *s;
  }
  const toml::table* table_;
  std::string name_;
  std::vector<std::string> used_;
};

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

Case resolve(const toml::table& doc, const std::string& source) {
  for (const auto& [k, v] : doc) {
    const std::string key(k.str());
    if (key != "bearing" && key != "material" && key != "operation" && key != "model")
      unknown_key(key);
  }
  Case c;
  c.source = source;

  TableReader bearing(top_table(doc, "bearing"), "bearing");
  if (auto p = bearing.text("preset", /*allow_integer=*/true)) {
    c.preset = *p;
    c.bearing = preset(*p);
  } else {
    // No preset: the geometry must be given in full; materials default to Harris's steel.
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

  TableReader material(top_table(doc, "material"), "material");
  read_material(material, {&b.ball, &b.rings});
  TableReader ball(material.subtable("ball"), "material.ball");
  read_material(ball, {&b.ball});
  ball.finish();
  TableReader rings(material.subtable("rings"), "material.rings");
  read_material(rings, {&b.rings});
  rings.finish();
  material.finish();

  TableReader operation(top_table(doc, "operation"), "operation");
  if (auto v = operation.quantity("speed")) c.operation.speed = *v;
  if (auto v = operation.vector2("load")) c.operation.load = *v;
  operation.finish();

  TableReader model(top_table(doc, "model"), "model");
  if (auto v = model.text("contact")) {
    if (*v == "calibrated")
      throw InputError(
          "model.contact = \"calibrated\": the FE-calibrated law is not available in "
          "this version (it needs bearing-fem calibrate); allowed: exact, "
          "hamrock-brewe, harris-table");
    make_hertz_solution(*v, "model.contact");  // throws for an unknown name, listing the allowed
    c.model.contact = *v;
  }
  model.finish();

  b.validate();
  if (!std::isfinite(c.operation.speed) || c.operation.speed < 0)
    throw InputError(
        "operation.speed = " + format_quantity(c.operation.speed, "rpm", Dimension::angular_speed) +
        ": must be >= 0 rpm (the inner ring turns counter-clockwise seen from +z)");
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

void apply_override(toml::table& doc, const Override& o) {
  std::vector<std::string> parts;
  std::stringstream ss(o.key);
  for (std::string p; std::getline(ss, p, '.');) parts.push_back(p);
  toml::table* t = &doc;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    toml::node* n = t->get(parts[i]);
    if (!n) {
      t->insert(parts[i], toml::table{});
      n = t->get(parts[i]);
    }
    if (!n->is_table())
      throw InputError("--set " + o.key + "=" + o.value + ": \"" + parts[i] +
                       "\" is a value, not a table");
    t = n->as_table();
  }
  toml::table parsed = override_value(o.value);
  t->insert_or_assign(parts.back(), std::move(*parsed.get("v")));
}

std::string with_source(const std::string& source, const std::string& message) {
  return source + ": " + message;
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
                      o.key.back() != '.' && o.key.find("..") == std::string::npos;
  if (!dotted) throw InputError("--set " + t + ": the key must be table.key, e.g. bearing.balls=9");
  if (o.value.empty()) throw InputError("--set " + t + ": no value after '='");
  return o;
}

Case parse_case(std::string_view toml_text, const std::string& source,
                const std::vector<Override>& overrides) {
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
    return resolve(doc, source);
  } catch (const InputError& e) {
    throw InputError(with_source(source, e.what()));
  }
}

Case read_case_file(const std::string& path, const std::vector<Override>& overrides) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot read the case file (" + std::strerror(errno) + ")");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path + ": cannot read the case file");
  return parse_case(text.str(), path, overrides);
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

std::string case_keys_help() {
  std::string out;
  for (const auto& k : schema()) {
    if (k.kind == Kind::table) continue;
    std::string units;
    if (k.kind == Kind::integer || k.kind == Kind::text || k.dim == Dimension::dimensionless) {
      units = k.kind == Kind::text ? "text" : "number";
    } else {
      for (const auto& u : accepted_units(k.dim)) units += (units.empty() ? "" : ", ") + u;
      units = (bare_number_is_si(k.dim) ? std::string(si_unit(k.dim)) + " if plain; "
                                        : "unit required; ") +
              units;
    }
    std::string name = k.name;
    name.resize(std::max<std::size_t>(name.size() + 1, 27), ' ');
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
