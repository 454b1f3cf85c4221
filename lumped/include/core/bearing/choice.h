#pragma once
// Enumerations a user picks by name (model.kind, solver.method, output.window, ...): each enum has
// one table of {value, name} pairs next to its definition, and the case reader turns the name
// into the value once, at the edge. Nothing downstream compares such strings.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bearing {

/// Throws InputError "`key` = "`name`": unknown `what`; allowed: a, b, c", with "(did you mean
/// "x"?)" when one of `names` is within three edits.
[[noreturn]] void throw_unknown_name(const std::string& key, std::string_view name,
                                     std::string_view what,
                                     const std::vector<std::string_view>& names);

/// One entry of an enum's name table.
template <class E>
struct Named {
  E value;
  const char* name;  ///< as written in case files and outputs
};

/// The value named `name` in `table`, or nothing.
template <class E, std::size_t N>
std::optional<E> find_named(const Named<E> (&table)[N], std::string_view name) {
  for (const Named<E>& entry : table)
    if (name == entry.name) return entry.value;
  return std::nullopt;
}

/// The name of `value` in `table` ("?" if the table lacks it, which a complete table never does).
template <class E, std::size_t N>
const char* name_of(const Named<E> (&table)[N], E value) {
  for (const Named<E>& entry : table)
    if (entry.value == value) return entry.name;
  return "?";
}

/// "a, b, c": the names of `table`, for messages and --help.
template <class E, std::size_t N>
std::string names_of(const Named<E> (&table)[N], std::string_view separator = ", ") {
  std::string out;
  for (const Named<E>& entry : table) {
    if (!out.empty()) out += separator;
    out += entry.name;
  }
  return out;
}

/// The value named `name`; InputError (throw_unknown_name) naming `key` otherwise.
template <class E, std::size_t N>
E parse_named(const Named<E> (&table)[N], std::string_view name, const std::string& key,
              std::string_view what) {
  if (const auto value = find_named(table, name)) return *value;
  std::vector<std::string_view> names;
  for (const Named<E>& entry : table) names.push_back(entry.name);
  throw_unknown_name(key, name, what, names);
}

}  // namespace bearing
