#include "toml_reader.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "../core/edit_distance.h"
#include "bearing/errors.h"
#include "case_schema.h"

namespace bearing::case_schema {

namespace {

std::string last_part(const std::string& dotted) {
  const auto dot = dotted.rfind('.');
  return dot == std::string::npos ? dotted : dotted.substr(dot + 1);
}

// The nearest known name to an unknown "table.key": the same key in another table, or the
// closest spelling.
std::string suggestion(const std::string& unknown) {
  const std::string leaf = last_part(unknown);
  for (const Key& k : keys())
    if (leaf == last_part(k.name) && unknown != k.name) return k.name;
  std::string best;
  std::size_t best_d = std::string::npos;
  for (const Key& k : keys()) {
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

}  // namespace

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
  else if (const toml::array* a = node.as_array()) {
    // Element by element: toml++ 3.3.0's array printer casts the log10 of a float below 1 to a
    // size_t, which is undefined (`load = [0.5, 0.1, 3]`; found by tests/fuzz/).
    s << "[";
    for (std::size_t i = 0; i < a->size(); ++i) s << (i ? ", " : " ") << shown_value(*a->get(i));
    s << (a->empty() ? "]" : " ]");
  } else
    node.visit([&s](auto&& n) { s << n; });
  return s.str();
}

std::string join(const std::vector<std::string>& items) {
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "" : ", ") + i;
  return s;
}

std::string fmt_si(double v, Dimension dim) {
  return format_number(v) + (si_unit(dim).empty() ? "" : " " + std::string(si_unit(dim)));
}

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

TableReader::TableReader(const toml::table* table, std::string shown, std::string schema)
    : table_(table), shown_(std::move(shown)), schema_(schema.empty() ? shown_ : schema) {}

const toml::node* TableReader::get(const std::string& key) {
  used_.push_back(key);
  return table_ ? table_->get(key) : nullptr;
}

Dimension TableReader::dim(const std::string& key) const {
  const Key* k = find_key(schema_ + "." + key);
  if (!k) throw std::logic_error("case schema: no row for " + schema_ + "." + key);
  return k->dim;
}

std::string TableReader::help(const std::string& key) const {
  const Key* k = find_key(schema_ + "." + key);
  if (!k) throw std::logic_error("case schema: no row for " + schema_ + "." + key);
  return k->help;
}

std::optional<double> TableReader::quantity(const std::string& key) {
  const toml::node* n = get(key);
  if (!n) return std::nullopt;
  return read_quantity(*n, full(key), dim(key));
}

std::optional<long long> TableReader::integer(const std::string& key) {
  const toml::node* n = get(key);
  if (!n) return std::nullopt;
  if (n->is_integer()) return n->value<long long>().value();
  if (n->is_floating_point()) {
    const double v = n->value<double>().value();
    throw InputError(
        full(key) + " = " + shown_value(*n) + ": expected a whole number (" + help(key) + ")" +
        (std::isfinite(v) && v == std::floor(v) ? ", write it without a decimal point" : ""));
  }
  throw InputError(full(key) + " = " + shown_value(*n) + ": expected an integer (" + help(key) +
                   "), got " + type_name(*n));
}

std::optional<std::string> TableReader::text(const std::string& key, bool allow_integer) {
  const toml::node* n = get(key);
  if (!n) return std::nullopt;
  if (n->is_string()) return n->value<std::string>().value();
  if (allow_integer && n->is_integer()) return std::to_string(n->value<long long>().value());
  throw InputError(full(key) + " = " + shown_value(*n) + ": expected a string (" + help(key) +
                   "), got " + type_name(*n));
}

std::optional<bool> TableReader::boolean(const std::string& key) {
  const toml::node* n = get(key);
  if (!n) return std::nullopt;
  if (n->is_boolean()) return n->value<bool>().value();
  throw InputError(full(key) + " = " + shown_value(*n) + ": expected true or false (" + help(key) +
                   "), got " + type_name(*n));
}

std::optional<Eigen::Vector2d> TableReader::vector2(const std::string& key) {
  const toml::node* n = get(key);
  if (!n) return std::nullopt;
  const toml::array* a = n->as_array();
  if (!a || a->size() != 2)
    throw InputError(full(key) + " = " + shown_value(*n) + ": expected two values [x, y] (" +
                     help(key) + "), e.g. [\"0 N\", \"-500 N\"]");
  Eigen::Vector2d v;
  for (int i = 0; i < 2; ++i)
    v[i] = read_quantity(*a->get(static_cast<std::size_t>(i)),
                         full(key) + "[" + std::to_string(i) + "]", dim(key));
  return v;
}

std::optional<std::vector<double>> TableReader::list(const std::string& key) {
  const toml::node* n = get(key);
  if (!n) return std::nullopt;
  const toml::array* a = n->as_array();
  if (!a)
    throw InputError(full(key) + " = " + shown_value(*n) + ": expected an array (" + help(key) +
                     "), e.g. [\"1 um\", \"-0.5 um\", ...]");
  std::vector<double> v;
  for (std::size_t i = 0; i < a->size(); ++i)
    v.push_back(read_quantity(*a->get(i), full(key) + "[" + std::to_string(i) + "]", dim(key)));
  return v;
}

std::optional<std::vector<Microphone>> TableReader::points(const std::string& key) {
  const toml::node* n = get(key);
  if (!n) return std::nullopt;
  const toml::array* a = n->as_array();
  const auto bad = [&](const std::string& what) {
    return InputError(full(key) + " = " + shown_value(*n) + ": " + what + " (" + help(key) +
                      "), e.g. [[\"10 mm\", \"-90 deg\"], [\"0.5 m\", \"0 deg\"]]");
  };
  if (!a) throw bad("expected an array of [r, angle] pairs");
  std::vector<Microphone> out;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::array* p = a->get(i)->as_array();
    if (!p || p->size() != 2) throw bad("entry " + std::to_string(i) + " is not a pair [r, angle]");
    const std::string shown = full(key) + "[" + std::to_string(i) + "]";
    out.push_back({read_quantity(*p->get(0), shown + "[0] (r)", Dimension::length),
                   read_quantity(*p->get(1), shown + "[1] (angle)", Dimension::angle)});
  }
  return out;
}

const toml::table* TableReader::subtable(const std::string& key) {
  const toml::node* n = get(key);
  if (!n) return nullptr;
  if (!n->is_table())
    throw InputError(full(key) + " = " + shown_value(*n) + ": expected a table [" + full(key) +
                     "] with " + keys_of_table(schema_ + "." + key) + ", got " + type_name(*n));
  return n->as_table();
}

const toml::array* TableReader::table_array(const std::string& key) {
  const toml::node* n = get(key);
  if (!n) return nullptr;
  const toml::array* a = n->as_array();
  if (!a || !a->is_array_of_tables())
    throw InputError(full(key) + " = " + shown_value(*n) + ": expected entries [[" + full(key) +
                     "]] with " + keys_of_table(schema_ + "." + key));
  return a;
}

void TableReader::finish() const {
  if (!table_) return;
  for (const auto& [k, v] : *table_) {
    const std::string key(k.str());
    if (std::find(used_.begin(), used_.end(), key) == used_.end())
      unknown_key(schema_ + "." + key, shown_ + "." + key);
  }
}

const toml::table* top_table(const toml::table& doc, const std::string& name) {
  const toml::node* n = doc.get(name);
  if (!n) return nullptr;
  if (!n->is_table())
    throw InputError(name + " = " + shown_value(*n) + ": expected a table [" + name + "] with " +
                     keys_of_table(name) + ", got " + type_name(*n));
  return n->as_table();
}

const toml::array* top_table_array(const toml::table& doc, const std::string& name) {
  const toml::node* n = doc.get(name);
  if (!n) return nullptr;
  const toml::array* a = n->as_array();
  if (!a || !a->is_array_of_tables())
    throw InputError(name + " = " + shown_value(*n) + ": expected entries [[" + name + "]] with " +
                     keys_of_table(name) + ", got " + type_name(*n));
  return a;
}

}  // namespace bearing::case_schema
