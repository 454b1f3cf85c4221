#pragma once
// Private to bearing_core: reading a JSON file that another program of the toolkit wrote
// (calibration.json of `bearing-fem calibrate`, modes.json of `bearing-fem modes`), with every
// fault an InputError that names the file, the key by its dotted path, the value and what is
// allowed. A user may hand over any bytes, so the parse is bounded (nesting depth) and no
// message prints more than a short excerpt of a value.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace bearing::json_document {

using nlohmann::json;

/// A JSON value as it appears in the file, shortened for a one-line message.
std::string shown_json(const json& j);
/// "a number", "an array", … for a message.
std::string article(const json& j);

/// Parses `text`; `shown` starts every message (e.g. `model.calibration = "cal.json"`),
/// `what_file` says what the file should be ("a calibration file written by bearing-fem
/// calibrate"), `levels` how deep such a file nests (nesting beyond 64 is refused while it is
/// read, before a message would print it). A number beyond a double's range is named by its key.
/// Throws InputError; the result is an object.
json parse(std::string_view text, const std::string& shown, const std::string& what_file,
           int levels);

/// Reads a whole file into a string; `shown` starts the message if it cannot (InputError).
/// `absolute` receives the file's absolute, normalised path.
std::string read_text(const std::string& path, const std::string& shown, std::string& absolute);

/// Reads the members of one JSON object, naming them by their dotted path in messages.
class Reader {
 public:
  /// `what_file` completes "X is missing (… has it)".
  Reader(const json& obj, std::string path, const std::string& shown, const std::string& what_file)
      : obj_(obj), path_(std::move(path)), shown_(shown), what_file_(what_file) {}

  [[noreturn]] void fail(const std::string& what) const;
  /// The dotted name of a member.
  std::string name(const char* key) const;

  /// A member that must be an object.
  Reader object(const char* key) const;
  /// A required finite number; `unit` is named in messages.
  double number(const char* key, const std::string& unit) const;
  /// An optional string ("" if absent).
  std::string text(const char* key) const;
  /// A required array (of any length).
  const json& array(const char* key) const;
  /// A required array of `size` finite numbers; `unit` is named in messages.
  std::vector<double> numbers(const char* key, std::size_t size, const std::string& unit) const;

  const json* get(const char* key) const;
  /// What starts every message.
  const std::string& shown() const { return shown_; }

 private:
  const json& obj_;
  std::string path_;
  const std::string& shown_;
  const std::string& what_file_;
};

}  // namespace bearing::json_document
