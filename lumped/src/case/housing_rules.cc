// The [housing] keys that need more than a value each (case_rules.h): the structure's modes file,
// a damping ratio for all modes or one per mode, and the sensors a run writes.

#include <cmath>
#include <string>
#include <vector>

#include "bearing/models/housing.h"
#include "bearing/structure_modes.h"
#include "case_rules.h"
#include "key_builders.h"
#include "toml_reader.h"

namespace bearing::case_schema {

namespace {

std::string join_path(const std::string& base_dir, const std::string& path) {
  if (base_dir.empty() || path.empty() || path.front() == '/') return path;
  return base_dir + "/" + path;
}

}  // namespace

void read_housing_modes(TableReader& r, Case& c, const ReadContext& context) {
  // An empty string means none, so that `--set 'housing.modes=""'` returns to the resonator.
  const auto file = r.text("modes");
  if (!file || file->empty()) return;
  c.housing.modes_file = *file;
  c.housing.modes =
      read_structure_modes(join_path(context.base_dir, *file), "housing.modes = \"" + *file + "\"");
}

void write_housing_modes(std::ostream& o, const Case& c) {
  if (c.housing.modes) o << "modes = " << quoted(c.housing.modes->path) << "\n";
}

void read_housing_damping(TableReader& r, Case& c, const ReadContext&) {
  const toml::node* n = r.node("damping_ratio");
  if (!n) return;
  if (n->is_array()) {
    c.housing.damping_ratios = *r.list("damping_ratio");
    if (c.housing.damping_ratios.empty())
      throw InputError(r.full("damping_ratio") +
                       " = []: give one damping ratio for all modes, or one per mode");
  } else {
    c.housing.damping_ratio = *r.quantity("damping_ratio");
  }
}

void write_housing_damping(std::ostream& o, const Case& c) {
  const Housing& h = c.housing;
  if (h.damping_ratios.empty()) {
    o << "damping_ratio = " << num17(h.damping_ratio) << "\n";
    return;
  }
  o << "damping_ratio = [";
  for (std::size_t k = 0; k < h.damping_ratios.size(); ++k)
    o << (k ? ", " : "") << num17(h.damping_ratios[k]);
  o << "]\n";
}

void read_housing_sensors(TableReader& r, Case& c, const ReadContext&) {
  const toml::node* n = r.node("sensors");
  if (!n) return;
  const auto bad = [&] {
    return InputError(r.full("sensors") + " = " + shown_value(*n) +
                      ": expected an array of the modes file's sensor names, e.g. [\"top\"]");
  };
  const toml::array* a = n->as_array();
  if (!a || a->empty()) throw bad();
  c.housing.sensors.clear();
  for (std::size_t i = 0; i < a->size(); ++i) {
    const auto name = a->get(i)->value<std::string>();
    if (!name) throw bad();
    c.housing.sensors.push_back(*name);
  }
}

void write_housing_sensors(std::ostream& o, const Case& c) {
  const Housing& h = c.housing;
  if (h.sensors.empty()) return;
  o << "sensors = [";
  for (std::size_t k = 0; k < h.sensors.size(); ++k) o << (k ? ", " : "") << quoted(h.sensors[k]);
  o << "]\n";
}

void check_housing_table(Case& c) {
  Housing& h = c.housing;
  if (!h.enabled) return;
  if (!h.modal()) {
    if (!h.damping_ratios.empty())
      throw InputError("housing.damping_ratio has " + std::to_string(h.damping_ratios.size()) +
                       " entries: one per mode needs housing.modes (the structure's modes); the "
                       "resonator (mass, frequency) has one damping ratio");
    if (!h.sensors.empty())
      throw InputError(
          "housing.sensors: sensors are points of the structure's modes (housing.modes); the "
          "resonator's sensor is the housing itself (ax_housing, ay_housing)");
  } else {
    // The resonator's required keys were left unset (NaN): the modes stand in for them.
    h.mass = 0.0;
    h.frequency = 0.0;
  }
  check_housing(h);
}

}  // namespace bearing::case_schema
