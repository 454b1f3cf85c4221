// The structure file of `bearing-fem modes` (structure_file.h): TOML through toml++ (after the
// guard against its 3.3.0 bugs), quantities through the lumped core's units, every range checked
// here, each error one line naming the file, the key, the value and what is allowed.

#include "modes/structure_file.h"

#include <toml++/toml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include "bearing/errors.h"
#include "bearing/toml_guard.h"
#include "bearing/units.h"
#include "mesh/gmsh_mesh.h"

namespace bearing::fem {

namespace {

using L = StructureLimits;

// A value for a message, never through toml++'s printer (its 3.3.0 float formatting is unsafe:
// tests/fuzz/README.md): strings quoted, numbers shortest, anything else by its type.
std::string shown(const toml::node& n) {
  if (const auto s = n.value_exact<std::string>()) {
    std::string out = "\"";
    for (char c : s->substr(0, 60)) out += (c >= 32 && c < 127) ? c : '?';
    return out + (s->size() > 60 ? "...\"" : "\"");
  }
  if (const auto i = n.value_exact<std::int64_t>()) return std::to_string(*i);
  if (const auto d = n.value_exact<double>()) return format_number(*d);
  if (n.is_boolean()) return n.value_exact<bool>().value() ? "true" : "false";
  if (n.is_array()) return "an array";
  if (n.is_table()) return "a table";
  return "a date or time";
}

// Reads one table's keys, refusing the ones it does not know.
class Table {
 public:
  Table(const toml::table* t, std::string name, const std::string& file,
        std::vector<std::string> known)
      : t_(t), name_(std::move(name)), file_(file), known_(std::move(known)) {
    if (!t_ || known_.empty()) return;  // no list: the caller checks every key itself
    for (const auto& [key, node] : *t_) {
      const std::string k(key.str());
      bool ok = false;
      for (const auto& q : known_) ok = ok || q == k;
      if (!ok) {
        std::string list;
        for (const auto& q : known_) list += (list.empty() ? "" : ", ") + q;
        fail(k, node, "unknown key (" + where() + " has: " + list + ")");
      }
    }
  }
  const toml::node* get(const std::string& key) const { return t_ ? t_->get(key) : nullptr; }
  std::string full(const std::string& key) const { return name_.empty() ? key : name_ + "." + key; }
  [[noreturn]] void fail(const std::string& key, const toml::node& n,
                         const std::string& what) const {
    throw InputError(file_ + ": " + full(key) + " = " + shown(n) + ": " + what);
  }
  [[noreturn]] void missing(const std::string& key, const std::string& what) const {
    throw InputError(file_ + ": " + full(key) + " is missing: " + what);
  }

 private:
  std::string where() const { return name_.empty() ? "the file's top level" : "[" + name_ + "]"; }
  const toml::table* t_;
  std::string name_;
  const std::string& file_;
  std::vector<std::string> known_;
};

std::string text_of(const Table& t, const std::string& key, const toml::node& n) {
  if (!n.is_string()) t.fail(key, n, "expected a string");
  return n.value_exact<std::string>().value();
}

// A quantity: a number (SI) or a string with a unit; in (low, high] or [low, high].
// `range` shows [low, high] or (low, high] as the message says it ("(0, 1e13]").
double quantity(const Table& t, const std::string& key, const toml::node& n, Dimension dim,
                double low, double high, bool low_open, const char* range,
                const std::string& unit) {
  double v = 0;
  if (n.is_integer() || n.is_floating_point())
    v = n.value<double>().value();
  else if (n.is_string())
    v = parse_quantity(n.value_exact<std::string>().value(), dim, t.full(key));
  else
    t.fail(key, n, "expected a number or a string with a unit");
  const bool ok = std::isfinite(v) && (low_open ? v > low : v >= low) && v <= high;
  if (!ok)
    t.fail(key, n,
           "must lie in " + std::string(range) + " " + unit +
               (n.is_string() ? " (read as " + format_number(v) + " " + unit + ")" : ""));
  return v;
}

bool sensor_name_ok(const std::string& s) {
  if (s.empty() || s.size() > 64) return false;
  for (char c : s)
    if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'))
      return false;
  return true;
}

void read_material(const toml::table& doc, StructureFile& s) {
  const auto* m = doc.get("material");
  if (!m) throw InputError(s.source + ": [material] is missing (young, poisson, density)");
  if (!m->is_table()) throw InputError(s.source + ": material must be a table [material]");
  const Table t(m->as_table(), "material", s.source, {"young", "poisson", "density"});
  const toml::node* young = t.get("young");
  const toml::node* poisson = t.get("poisson");
  const toml::node* density = t.get("density");
  if (!young) t.missing("young", "Young's modulus, e.g. \"210 GPa\"");
  if (!poisson) t.missing("poisson", "Poisson's ratio, e.g. 0.3");
  if (!density) t.missing("density", "the density, e.g. \"7850 kg/m^3\"");
  s.young =
      quantity(t, "young", *young, Dimension::pressure, 0, L::max_young, true, "(0, 1e13]", "Pa");
  if (!(poisson->is_integer() || poisson->is_floating_point()))
    t.fail("poisson", *poisson, "expected a number");
  s.poisson = poisson->value<double>().value();
  if (!(s.poisson >= 0 && s.poisson < 0.5)) t.fail("poisson", *poisson, "must lie in [0, 0.5)");
  s.density = quantity(t, "density", *density, Dimension::density, 0, L::max_density, true,
                       "(0, 1e5]", "kg/m^3");
}

void read_boundary(const toml::table& doc, StructureFile& s) {
  const auto* b = doc.get("boundary");
  if (!b) throw InputError(s.source + ": [boundary] is missing (seat, and fixed unless free-free)");
  if (!b->is_table()) throw InputError(s.source + ": boundary must be a table [boundary]");
  const Table t(b->as_table(), "boundary", s.source, {"fixed", "seat"});
  if (const toml::node* f = t.get("fixed")) {
    if (!f->is_array()) t.fail("fixed", *f, "expected an array of physical surface names");
    const toml::array& a = *f->as_array();
    if (a.size() > L::max_fixed)
      t.fail("fixed", *f, "at most " + std::to_string(L::max_fixed) + " surfaces");
    for (const toml::node& e : a) {
      if (!e.is_string() || e.value_exact<std::string>()->empty())
        t.fail("fixed", e, "expected the name of a physical surface (a non-empty string)");
      const std::string name = e.value_exact<std::string>().value();
      for (const std::string& q : s.fixed)
        if (q == name) t.fail("fixed", e, "named twice");
      s.fixed.push_back(name);
    }
  }
  const toml::node* seat = t.get("seat");
  if (!seat) t.missing("seat", "the physical surface the bearing's outer ring sits in");
  s.seat = text_of(t, "seat", *seat);
  if (s.seat.empty()) t.fail("seat", *seat, "expected the name of a physical surface");
}

void read_sensors(const toml::table& doc, StructureFile& s) {
  const auto* n = doc.get("sensors");
  if (!n) return;
  if (!n->is_table()) throw InputError(s.source + ": sensors must be a table [sensors]");
  const toml::table& table = *n->as_table();
  if (table.size() > L::max_sensors)
    throw InputError(s.source + ": [sensors] has " + std::to_string(table.size()) +
                     " points: at most " + std::to_string(L::max_sensors));
  for (const auto& [key, node] : table) {
    const std::string name(key.str());
    const Table t(&table, "sensors", s.source, {});  // every name is a key: checked below
    if (!sensor_name_ok(name))
      t.fail(name, node, "a sensor's name must match [A-Za-z0-9_]+ (at most 64 characters)");
    if (!node.is_array() || node.as_array()->size() != 3)
      t.fail(name, node, "expected a point [x, y, z] in mesh units (" + s.mesh_unit + ")");
    StructureSensor sensor;
    sensor.name = name;
    for (std::size_t k = 0; k < 3; ++k) {
      const toml::node& c = *node.as_array()->get(k);
      const double v = c.value<double>().value_or(NAN);
      if (!(c.is_integer() || c.is_floating_point()) || !(std::fabs(v) <= L::max_coordinate))
        t.fail(name, c, "each coordinate must be a finite number of mesh units, |x| <= 1e9");
      sensor.written[k] = v;
      sensor.point[k] = v * s.mesh_scale;
    }
    s.sensors.push_back(sensor);
  }
}

}  // namespace

StructureFile parse_structure(std::string_view text, const std::string& source) {
  StructureFile s;
  s.source = source;
  if (const auto p = case_schema::unsafe_toml_text(text))
    throw InputError(source + ":" + std::to_string(p->line) + ":" + std::to_string(p->column) +
                     ": TOML syntax error: " + p->what);
  toml::table doc;
  try {
    doc = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    const auto& where = e.source().begin;
    throw InputError(source + ":" + std::to_string(where.line) + ":" +
                     std::to_string(where.column) +
                     ": TOML syntax error: " + std::string(e.description()));
  }
  const Table top(&doc, "", source,
                  {"mesh", "mesh_unit", "material", "boundary", "sensors", "modes"});
  const toml::node* mesh = top.get("mesh");
  if (!mesh) top.missing("mesh", "the gmsh mesh file (.msh 2.2 or 4.1), relative to this file");
  s.mesh = text_of(top, "mesh", *mesh);
  if (s.mesh.empty() || s.mesh.find('\0') != std::string::npos)
    top.fail("mesh", *mesh, "expected a file name");
  const std::filesystem::path folder = std::filesystem::path(source).parent_path();
  const std::filesystem::path m(s.mesh);
  s.mesh_path = (m.is_absolute() || folder.empty() ? m : folder / m).string();
  if (const toml::node* u = top.get("mesh_unit")) {
    s.mesh_unit = text_of(top, "mesh_unit", *u);
    if (s.mesh_unit != "m" && s.mesh_unit != "mm") top.fail("mesh_unit", *u, "must be m or mm");
  }
  s.mesh_scale = s.mesh_unit == "mm" ? 1e-3 : 1.0;
  read_material(doc, s);
  read_boundary(doc, s);
  read_sensors(doc, s);
  if (const auto* n = doc.get("modes")) {
    if (!n->is_table()) throw InputError(source + ": modes must be a table [modes]");
    const Table t(n->as_table(), "modes", source, {"count", "max_frequency"});
    if (const toml::node* c = t.get("count")) {
      const auto v = c->value_exact<std::int64_t>();
      if (!v || *v < 1 || *v > static_cast<std::int64_t>(L::max_count))
        t.fail("count", *c, "must be a whole number in [1, " + std::to_string(L::max_count) + "]");
      s.count = static_cast<unsigned int>(*v);
    }
    if (const toml::node* f = t.get("max_frequency"))
      s.max_frequency = quantity(t, "max_frequency", *f, Dimension::frequency, 0, L::max_frequency,
                                 true, "(0, 1e7]", "Hz");
  }
  if (s.count == 0 && s.max_frequency == 0) s.count = 20;
  return s;
}

StructureFile read_structure_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the structure file");
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw InputError(path + ": cannot read the structure file");
  return parse_structure(text, path);
}

void check_structure_against_mesh(const StructureFile& s, const GmshMesh& mesh) {
  const auto check = [&](const std::string& key, const std::string& name) {
    if (mesh.surface_tag(name) != 0) return;
    bool volume = false;
    for (const PhysicalName& p : mesh.names)
      volume = volume || (p.dimension != 2 && p.name == name);
    throw InputError(s.source + ": " + key + " = \"" + name + "\": " +
                     (volume ? "a physical group of the mesh that is not a surface"
                             : "no physical surface of that name") +
                     " in " + mesh.file + " (its physical surfaces: " + mesh.surface_names() + ")");
  };
  for (const std::string& f : s.fixed) check("boundary.fixed", f);
  check("boundary.seat", s.seat);
  for (const std::string& f : s.fixed)
    if (f == s.seat)
      throw InputError(s.source + ": boundary.seat = \"" + s.seat +
                       "\" is also in boundary.fixed: a held seat does not move");
}

}  // namespace bearing::fem
