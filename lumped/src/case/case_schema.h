#pragma once
// Private to the case reader: the schema, one row per case-file key. A row says what the key is
// (kind, dimension, one line of help with its default and allowed range), where its value lands
// in a Case, the check of its range, and how it is written back; reading, writing (case.toml),
// --help, dimension lookup (sweeps) and range checks are all driven by these rows. A table row
// (kind table) carries what concerns several keys at once: when the table may appear, and the
// rules that tie its keys together. Each check is written once, here or in the domain type's own
// validate() (Bearing, Material) that a table row calls.

#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "bearing/case_file.h"
#include "toml_reader.h"

namespace bearing::case_schema {

enum class Kind {
  quantity,
  integer,
  text,
  choice,
  boolean,
  vector2,
  list,
  points,
  table,
  table_array
};

/// What reading a key needs besides its table: where relative file names start.
struct ReadContext {
  std::string base_dir;
};

struct Key {
  std::string name;  ///< "rotor.mass"; an entry key of an array of tables: "waviness.inner.order"
  Kind kind = Kind::quantity;
  Dimension dim = Dimension::dimensionless;
  std::string help;  ///< one line for --help: what it is, its default and allowed range
  /// Lands the key's value in the case (or its default when the key is absent). Empty for entry
  /// keys, which their table_array row reads. On a table row: reads the keys that only make sense
  /// together (after the keys' own reads, before the unknown keys are reported).
  std::function<void(TableReader&, Case&, const ReadContext&)> read;
  /// The range check of the landed value, run once the whole table is read.
  std::function<void(const Case&)> check;
  /// Writes the key's lines of the resolved case ("name = value\n"); empty: not written.
  std::function<void(std::ostream&, const Case&)> write;

  // Table rows only.
  /// Runs before the table is read (e.g. a table only one model kind uses).
  std::function<void(const TableReader&, Case&)> before;
  /// The rules that tie the table's keys together, run after its keys and their checks.
  std::function<void(Case&)> after;
  /// Writes the whole table itself (entries, comments); empty: "[name]" and the keys' lines.
  std::function<void(std::ostream&, const Case&)> write_table;
  /// Whether case.toml has this table (empty: always).
  std::function<bool(const Case&)> written;
};

/// Every row, in reading, writing and --help order; tables before their keys.
const std::vector<Key>& keys();

/// The row named `name` (schema spelling, no array indices), or nullptr.
const Key* find_key(const std::string& name);

/// The top-level table names.
std::vector<std::string> top_tables();

/// "a, b, c": the keys directly under `table`.
std::string keys_of_table(const std::string& table);

/// Resolves a parsed case file: every row read, checked and defaulted.
Case resolve(const toml::table& doc, const std::string& source, const ReadContext& context);

/// The resolved case as TOML (case_to_toml).
std::string write_case(const Case& c);

}  // namespace bearing::case_schema
