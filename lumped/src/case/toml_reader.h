#pragma once
// Private to the case reader: typed reads of one TOML table's keys, each error naming the key as
// the user wrote it, the value and what is allowed; the keys nobody asked for are reported as
// unknown, with the nearest valid name.

#include <optional>
#include <string>
#include <vector>

#include <toml++/toml.h>
#include <Eigen/Dense>

#include "bearing/acoustics/acoustics_options.h"
#include "bearing/units.h"

namespace bearing::case_schema {

/// "a string", "an integer", ... for messages.
std::string type_name(const toml::node& node);
/// The node as written ("\"2 um\"", "3", "{...}").
std::string shown_value(const toml::node& node);
/// "a, b, c".
std::string join(const std::vector<std::string>& items);
/// A number in SI with its SI unit ("0.005 m").
std::string fmt_si(double v, Dimension dim);

/// A quantity: a plain number (SI) or a string with a unit; `key` as shown in messages.
double read_quantity(const toml::node& node, const std::string& key, Dimension dim);

/// Throws InputError for an unknown key `name` (schema spelling), shown as the user wrote it, with
/// the nearest known name and the keys of its table.
[[noreturn]] void unknown_key(const std::string& name, const std::string& shown);

/// Reads the keys of one table, remembering which were asked for so the rest can be reported.
class TableReader {
 public:
  /// `shown` names the table in messages ("waviness.inner[2]"), `schema` in the schema
  /// ("waviness.inner").
  TableReader(const toml::table* table, std::string shown, std::string schema = "");

  bool present() const { return table_ != nullptr; }
  bool has(const std::string& key) const { return table_ && table_->get(key); }
  std::string full(const std::string& key) const { return shown_ + "." + key; }
  const std::string& schema() const { return schema_; }
  /// The table as shown in messages ("defects[2]").
  const std::string& shown() const { return shown_; }

  std::optional<double> quantity(const std::string& key);
  std::optional<long long> integer(const std::string& key);
  std::optional<std::string> text(const std::string& key, bool allow_integer = false);
  std::optional<bool> boolean(const std::string& key);
  std::optional<Eigen::Vector2d> vector2(const std::string& key);
  std::optional<std::vector<double>> list(const std::string& key);
  /// An array of [r, angle] pairs: a length and an angle each.
  std::optional<std::vector<Microphone>> points(const std::string& key);
  /// The node of `key` as written (nullptr if absent), for a key whose row reads it itself.
  const toml::node* node(const std::string& key) { return get(key); }
  const toml::table* subtable(const std::string& key);
  const toml::array* table_array(const std::string& key);
  /// Throws for the first key of the table that no read asked for.
  void finish() const;

 private:
  const toml::node* get(const std::string& key);
  Dimension dim(const std::string& key) const;
  std::string help(const std::string& key) const;

  const toml::table* table_;
  std::string shown_;
  std::string schema_;
  std::vector<std::string> used_;
};

/// The top-level table `name` of `doc`, or nullptr; InputError if it is not a table.
const toml::table* top_table(const toml::table& doc, const std::string& name);

/// The top-level array of tables `name` ([[name]] entries) of `doc`, or nullptr; InputError if it
/// is something else.
const toml::array* top_table_array(const toml::table& doc, const std::string& name);

}  // namespace bearing::case_schema
