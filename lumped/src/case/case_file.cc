// Case files (case_file.h): the command-line overrides, parsing, and the schema's services.
// Every key itself is a row of the schema (case/case_keys.cc).

#include "bearing/case_file.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <toml++/toml.h>

#include "bearing/errors.h"
#include "bearing/hertz.h"
#include "bearing/toml_guard.h"
#include "case_schema.h"
#include "toml_reader.h"

namespace bearing {

namespace {

// Parses an override value as TOML; anything that is not valid TOML is taken as a string.
toml::table override_value(const std::string& value) {
  const std::string text = "v = " + value;
  if (!case_schema::unsafe_toml_text(text)) {  // else toml++ 3.3.0 would misbehave on it
    try {
      return toml::parse(text);
    } catch (const toml::parse_error&) {
    }
  }
  toml::table t;
  t.insert("v", value);
  return t;
}

bool is_index(const std::string& part) {
  return !part.empty() &&
         std::all_of(part.begin(), part.end(), [](unsigned char c) { return std::isdigit(c); });
}

void apply_override(toml::table& doc, const Override& o) {
  std::vector<std::string> parts;
  std::stringstream ss(o.key);
  for (std::string p; std::getline(ss, p, '.');) parts.push_back(p);
  const std::string where = "--set " + o.key + "=" + o.value + ": ";
  toml::node* node = &doc;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    if (toml::array* a = node->as_array(); a && is_index(parts[i])) {
      // At most 18 digits: they fit a std::size_t (std::stoul would throw beyond it).
      const bool fits = parts[i].size() <= 18;
      const std::size_t index = fits ? std::stoull(parts[i]) : 0;
      if (!fits || index >= a->size())
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
  if (const auto p = case_schema::unsafe_toml_text(toml_text))
    throw InputError(source + ":" + std::to_string(p->line) + ":" + std::to_string(p->column) +
                     ": TOML syntax error: " + p->what);
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
    return case_schema::resolve(doc, source, {base_dir});
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

std::string case_to_toml(const Case& c) {
  return case_schema::write_case(c);
}

ContactConstants contact_constants(const Case& c) {
  if (c.model.contact == ContactLaw::calibrated) {
    if (!c.model.calibration)
      throw InputError("model.contact = \"calibrated\" needs model.calibration");
    return calibrated_contact_constants(c.bearing, *c.model.calibration);
  }
  return contact_constants(c.bearing, *make_hertz_solution(hertz_shape_method(c.model)));
}

HertzMethod hertz_shape_method(const ModelOptions& m) {
  return hertz_shape_method(m.contact);
}

Dimension key_dimension(const std::string& key) {
  using case_schema::Kind;
  const case_schema::Key* k = case_schema::find_key(schema_name(key));
  if (!k) case_schema::unknown_key(schema_name(key), key);  // with the nearest known key
  if (!(k->kind == Kind::quantity || k->kind == Kind::integer))
    throw InputError(key + ": not a numeric case-file key (see bearing-sim run --help)");
  return k->dim;
}

bool key_is_integer(const std::string& key) {
  const case_schema::Key* k = case_schema::find_key(schema_name(key));
  return k && k->kind == case_schema::Kind::integer;
}

std::string case_keys_help() {
  using case_schema::Kind;
  std::string out;
  for (const case_schema::Key& k : case_schema::keys()) {
    if (k.kind == Kind::table) continue;
    std::string units;
    if (k.kind == Kind::points) {
      units = "pairs of a length and an angle (deg or rad)";
    } else if (k.kind == Kind::quantity || k.kind == Kind::vector2 || k.kind == Kind::list) {
      units = k.dim == Dimension::dimensionless
                  ? "number"
                  : (bare_number_is_si(k.dim) ? std::string(si_unit(k.dim)) + " if plain; "
                                              : "unit required; ") +
                        case_schema::join(accepted_units(k.dim));
    } else {
      units = k.kind == Kind::text || k.kind == Kind::choice ? "text"
              : k.kind == Kind::boolean                      ? "true/false"
              : k.kind == Kind::table_array                  ? "entries"
                                                             : "number";
    }
    std::string name = k.name;
    name.resize(std::max<std::size_t>(name.size() + 1, 30), ' ');
    out += "  " + name + k.help + " [" + units + "]\n";
  }
  return out;
}

std::vector<std::string> known_keys() {
  std::vector<std::string> out;
  for (const case_schema::Key& k : case_schema::keys())
    if (k.kind != case_schema::Kind::table) out.push_back(k.name);
  return out;
}

}  // namespace bearing
