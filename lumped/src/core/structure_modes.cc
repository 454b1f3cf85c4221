// A modes file of `bearing-fem modes` read back (structure_modes.h): its keys are spelled here.

#include "bearing/structure_modes.h"

#include <cctype>
#include <cmath>
#include <set>

#include "bearing/errors.h"
#include "bearing/units.h"
#include "json_document.h"

namespace bearing {

namespace {

using json_document::article;
using json_document::json;
using json_document::Reader;
using json_document::shown_json;

const std::string kWhatFile = "a modes file written by bearing-fem modes";

// The units this version reads, where the file declares them.
constexpr std::pair<const char*, const char*> kUnits[] = {
    {"frequency", "Hz"}, {"length", "m"}, {"shape", "kg^-1/2"}};

void check_format(const Reader& top) {
  const json* format = top.get("format");
  const std::string expected = "expected \"" + std::string(kModesFormat) + "\" (" + kWhatFile + ")";
  if (!format) top.fail("format is missing: " + expected);
  if (!(format->is_string() && format->get<std::string>() == kModesFormat))
    top.fail("format = " + shown_json(*format) + ": " + expected);
  const double version = top.number("version", "");
  if (version != kModesVersion)
    top.fail("version = " + format_number(version) + ": this program reads version " +
             std::to_string(kModesVersion));
  if (const json* u = top.get("units")) {
    if (!u->is_object())
      top.fail("units = " + shown_json(*u) + ": expected an object, got " + article(*u));
    const Reader units = top.object("units");
    for (const auto& [key, unit] : kUnits) {
      const json* v = units.get(key);
      if (v && !(v->is_string() && v->get<std::string>() == unit))
        top.fail(std::string("units.") + key + " = " + shown_json(*v) + ": expected \"" + unit +
                 "\" (modes files are in SI units, shapes mass-normalised)");
    }
  }
}

std::vector<double> read_frequencies(const Reader& top) {
  const json& a = top.array("frequencies");
  if (a.empty() || a.size() > static_cast<std::size_t>(kMaxStructureModes))
    top.fail("frequencies has " + std::to_string(a.size()) + " entries: expected 1 to " +
             std::to_string(kMaxStructureModes) + " modes");
  const std::vector<double> f = top.numbers("frequencies", a.size(), "Hz");
  for (std::size_t k = 0; k < f.size(); ++k) {
    const std::string at = "frequencies[" + std::to_string(k) + "] = " + format_number(f[k]);
    if (!(f[k] > 0)) top.fail(at + " Hz: must be positive (rigid-body modes are not returned)");
    if (k > 0 && f[k] < f[k - 1])
      top.fail(at + " Hz: below frequencies[" + std::to_string(k - 1) +
               "] = " + format_number(f[k - 1]) + " Hz; the modes must be in ascending order");
  }
  if (const json* count = top.get("count")) {
    const double n = top.number("count", "");
    if (n != static_cast<double>(f.size()))
      top.fail("count = " + shown_json(*count) + ": the file has " + std::to_string(f.size()) +
               " frequencies");
  }
  return f;
}

std::array<std::vector<double>, 3> read_xyz(const Reader& r, std::size_t modes) {
  return {r.numbers("x", modes, "kg^-1/2"), r.numbers("y", modes, "kg^-1/2"),
          r.numbers("z", modes, "kg^-1/2")};
}

bool valid_sensor_name(const std::string& name) {
  if (name.empty() || name.size() > 64) return false;
  for (const char ch : name)
    if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '_')) return false;
  return true;
}

std::vector<StructureSensor> read_sensors(const Reader& top, std::size_t modes) {
  std::vector<StructureSensor> out;
  const json* list = top.get("sensors");
  if (!list) return out;
  const json& a = top.array("sensors");
  std::set<std::string> seen;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::string at = "sensors[" + std::to_string(i) + "]";
    if (!a[i].is_object())
      top.fail(at + " = " + shown_json(a[i]) + ": expected an object, got " + article(a[i]));
    const Reader r(a[i], at, top.shown(), kWhatFile);
    StructureSensor s;
    s.name = r.text("name");
    if (!valid_sensor_name(s.name))
      r.fail(r.name("name") + " = " + shown_json(json(s.name)) +
             ": a sensor's name is 1 to 64 letters, digits or '_' (it names the channels "
             "ax_<name>, ay_<name>, az_<name>)");
    if (!seen.insert(s.name).second)
      r.fail(r.name("name") + " = \"" + s.name + "\": two sensors have this name");
    const std::vector<double> p = r.numbers("point", 3, "m");
    s.point = {p[0], p[1], p[2]};
    s.shape = read_xyz(r, modes);
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace

const StructureSensor* StructureModes::sensor(const std::string& name) const {
  for (const StructureSensor& s : sensors)
    if (s.name == name) return &s;
  return nullptr;
}

StructureModes parse_structure_modes(std::string_view json_text, const std::string& path,
                                     const std::string& shown) {
  // The deepest value: sensors[i].x[k], 4 levels.
  const json doc = json_document::parse(json_text, shown, kWhatFile, 4);
  const Reader top(doc, "", shown, kWhatFile);
  check_format(top);

  StructureModes m;
  m.path = path;
  const Reader boundary = top.object("boundary");
  const json* free = boundary.get("free");
  if (!free || !free->is_boolean())
    boundary.fail("boundary.free = " + (free ? shown_json(*free) : std::string("(missing)")) +
                  ": expected true or false (whether no surface of the structure is held)");
  m.free = free->get<bool>();
  m.frequencies = read_frequencies(top);
  m.seat = read_xyz(top.object("seat"), m.frequencies.size());
  m.sensors = read_sensors(top, m.frequencies.size());
  return m;
}

StructureModes read_structure_modes(const std::string& path, const std::string& shown) {
  std::string absolute;
  const std::string text = json_document::read_text(path, shown, absolute);
  return parse_structure_modes(text, absolute, shown);
}

}  // namespace bearing
