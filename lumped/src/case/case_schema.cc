// Reading and writing a case by its schema rows (case_schema.h).

#include "case_schema.h"

#include <algorithm>
#include <sstream>
#include <string>

namespace bearing::case_schema {

namespace {

// "material.ball" is directly under "material"; "material.ball.young" is not.
bool directly_under(const std::string& name, const std::string& table) {
  return name.size() > table.size() + 1 && name.compare(0, table.size(), table) == 0 &&
         name[table.size()] == '.' && name.find('.', table.size() + 1) == std::string::npos;
}

bool top_level(const Key& k) {
  return (k.kind == Kind::table || k.kind == Kind::table_array) &&
         k.name.find('.') == std::string::npos;
}

// A top-level array of tables ([[defects]]): the row reads one entry; its rules run on them all.
void read_entries(const toml::table& doc, const Key& row, Case& c, const ReadContext& context) {
  if (const toml::array* entries = top_table_array(doc, row.name))
    for (std::size_t i = 0; i < entries->size(); ++i) {
      TableReader r(entries->get(i)->as_table(), row.name + "[" + std::to_string(i) + "]",
                    row.name);
      row.read(r, c, context);
      r.finish();
    }
  if (row.after) row.after(c);
}

// Reads one table: its keys in schema order (sub-tables recursively), the table's own reading of
// keys that belong together, the unknown keys, each key's check, then the table's rules.
void read_table(TableReader& r, const Key& table, Case& c, const ReadContext& context) {
  if (table.before) table.before(r, c);
  for (const Key& k : keys()) {
    if (!directly_under(k.name, table.name)) continue;
    if (k.kind == Kind::table) {
      TableReader sub(r.subtable(k.name.substr(table.name.size() + 1)), k.name);
      read_table(sub, k, c, context);
    } else if (k.read) {
      k.read(r, c, context);
    }
  }
  if (table.read) table.read(r, c, context);
  r.finish();
  for (const Key& k : keys())
    if (directly_under(k.name, table.name) && k.check) k.check(c);
  if (table.after) table.after(c);
}

// The blocks of one table in case.toml: "[name]" and its keys' lines, then its sub-tables.
void write_table(const Key& table, const Case& c, std::vector<std::string>& blocks) {
  if (table.written && !table.written(c)) return;
  std::ostringstream o;
  if (table.write_table) {
    table.write_table(o, c);
    if (!o.str().empty()) blocks.push_back(o.str());
    return;
  }
  for (const Key& k : keys())
    if (directly_under(k.name, table.name) && k.kind != Kind::table && k.write) k.write(o, c);
  if (!o.str().empty()) blocks.push_back("[" + table.name + "]\n" + o.str());
  for (const Key& k : keys())
    if (directly_under(k.name, table.name) && k.kind == Kind::table) write_table(k, c, blocks);
}

}  // namespace

const Key* find_key(const std::string& name) {
  for (const Key& k : keys())
    if (k.name == name) return &k;
  return nullptr;
}

std::vector<std::string> top_tables() {
  std::vector<std::string> out;
  for (const Key& k : keys())
    if (top_level(k)) out.push_back(k.name);
  return out;
}

std::string keys_of_table(const std::string& table) {
  std::string out;
  for (const Key& k : keys())
    if (directly_under(k.name, table))
      out += (out.empty() ? "" : ", ") + k.name.substr(table.size() + 1);
  return out;
}

Case resolve(const toml::table& doc, const std::string& source, const ReadContext& context) {
  const std::vector<std::string> tables = top_tables();
  for (const auto& [k, v] : doc) {
    const std::string key(k.str());
    if (std::find(tables.begin(), tables.end(), key) == tables.end()) unknown_key(key, key);
  }
  Case c;
  c.source = source;
  for (const Key& t : keys()) {
    if (!top_level(t)) continue;
    if (t.kind == Kind::table_array) {
      read_entries(doc, t, c, context);
      continue;
    }
    TableReader r(top_table(doc, t.name), t.name);
    read_table(r, t, c, context);
  }
  return c;
}

std::string write_case(const Case& c) {
  std::vector<std::string> blocks;
  for (const Key& t : keys())
    if (top_level(t)) write_table(t, c, blocks);
  std::string out =
      "# Fully resolved case (SI units: m, kg, s, N, Pa, rad, rad/s, Hz), written by "
      "bearing-sim.\n# Source: " +
      c.source + (c.preset.empty() ? "" : ", preset " + c.preset) + "\n\n";
  for (std::size_t i = 0; i < blocks.size(); ++i) out += (i ? "\n" : "") + blocks[i];
  return out;
}

}  // namespace bearing::case_schema
