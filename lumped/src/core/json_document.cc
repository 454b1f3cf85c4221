// Reading a JSON file another program of the toolkit wrote (json_document.h).

#include "json_document.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>
#include <vector>

#include "bearing/errors.h"
#include "bearing/units.h"

namespace bearing::json_document {

namespace {

std::string dotted(const std::string& path, const char* key) {
  return path.empty() ? std::string(key) : path + "." + key;
}

const json* member(const json& obj, const char* key) {
  const auto it = obj.find(key);
  return it == obj.end() ? nullptr : &*it;
}

}  // namespace

std::string shown_json(const json& j) {
  std::string s = j.dump();
  if (s.size() > 60) s = s.substr(0, 57) + "...";
  return s;
}

std::string article(const json& j) {
  const std::string t = j.type_name();
  return (t == "array" || t == "object" ? "an " : "a ") + t;
}

json parse(std::string_view text, const std::string& shown, const std::string& what_file,
           int levels) {
  // The parser callback tracks the key path, so that a number beyond the range of a double
  // (which the parser rejects itself) can be named.
  std::vector<std::string> where;
  const auto key_path = [&where] {
    std::string key;
    for (const auto& w : where)
      if (!w.empty()) key += (key.empty() ? "" : ".") + w;
    return key;
  };
  // Deeper nesting is refused while it is read, before a message would print it (recursively:
  // a few 100 kB of "[[[[" overflowed the stack).
  constexpr std::size_t kMaxDepth = 64;
  const json::parser_callback_t track = [&](int depth, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        if (static_cast<std::size_t>(depth) >= kMaxDepth)
          throw InputError(shown + ": " +
                           (key_path().empty() ? std::string("a value") : key_path()) +
                           " is nested deeper than " + std::to_string(kMaxDepth) + " levels (" +
                           what_file + " has " + std::to_string(levels) + ")");
        where.emplace_back();
        break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        if (!where.empty()) where.pop_back();
        break;
      case json::parse_event_t::key:
        if (!where.empty()) where.back() = parsed.get<std::string>();
        break;
      default:
        break;
    }
    return true;
  };
  // nlohmann's messages start with "[json.exception.<kind>.<id>] ".
  const auto message = [](const json::exception& e) {
    std::string what = e.what();
    if (const auto end = what.find("] "); what.rfind("[json.exception", 0) == 0 && end != what.npos)
      what.erase(0, end + 2);
    std::replace(what.begin(), what.end(), '\n', ' ');
    return what;
  };
  json doc;
  try {
    doc = json::parse(text.begin(), text.end(), track);
  } catch (const json::out_of_range& e) {  // 406: a number overflowing a double
    const std::string key = key_path();
    throw InputError(shown + ": " + (key.empty() ? std::string("a number") : key) + ": " +
                     message(e) + "; every number must be finite");
  } catch (const json::exception& e) {
    throw InputError(shown + ": not valid JSON (" + message(e) + ")");
  }
  if (!doc.is_object())
    throw InputError(shown + ": expected a JSON object (" + what_file + "), got " + article(doc));
  return doc;
}

std::string read_text(const std::string& path, const std::string& shown, std::string& absolute) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path full = fs::absolute(path, ec);
  if (ec) full = path;
  full = full.lexically_normal();
  absolute = full.string();
  std::ifstream in(full, std::ios::binary);
  if (!in)
    throw InputError(shown + ": cannot read " + absolute + " (" + std::strerror(errno) + ")");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(shown + ": cannot read " + absolute);
  return text.str();
}

void Reader::fail(const std::string& what) const {
  throw InputError(shown_ + ": " + what);
}

std::string Reader::name(const char* key) const {
  return dotted(path_, key);
}

const json* Reader::get(const char* key) const {
  return member(obj_, key);
}

Reader Reader::object(const char* key) const {
  const json* v = member(obj_, key);
  if (!v) fail(name(key) + " is missing (" + what_file_ + " has it)");
  if (!v->is_object())
    fail(name(key) + " = " + shown_json(*v) + ": expected an object, got " + article(*v));
  return Reader(*v, name(key), shown_, what_file_);
}

double Reader::number(const char* key, const std::string& unit) const {
  const json* v = member(obj_, key);
  const std::string in = unit.empty() ? "" : " in " + unit;
  if (!v) fail(name(key) + " is missing: expected a number" + in);
  if (!v->is_number())
    fail(name(key) + " = " + shown_json(*v) + ": expected a number" + in + ", got " + article(*v));
  const double d = v->get<double>();
  if (!std::isfinite(d))
    fail(name(key) + " = " + format_number(d) + ": must be a finite number" + in);
  return d;
}

std::string Reader::text(const char* key) const {
  const json* v = member(obj_, key);
  if (!v) return "";
  if (!v->is_string())
    fail(name(key) + " = " + shown_json(*v) + ": expected a string, got " + article(*v));
  return v->get<std::string>();
}

const json& Reader::array(const char* key) const {
  const json* v = member(obj_, key);
  if (!v) fail(name(key) + " is missing (" + what_file_ + " has it)");
  if (!v->is_array())
    fail(name(key) + " = " + shown_json(*v) + ": expected an array, got " + article(*v));
  return *v;
}

std::vector<double> Reader::numbers(const char* key, std::size_t size,
                                    const std::string& unit) const {
  const json& a = array(key);
  const std::string in = unit.empty() ? "" : " in " + unit;
  if (a.size() != size)
    fail(name(key) + " has " + std::to_string(a.size()) + " entries: expected " +
         std::to_string(size));
  std::vector<double> out;
  out.reserve(size);
  for (std::size_t i = 0; i < a.size(); ++i) {
    const json& e = a[i];
    const std::string at = name(key) + "[" + std::to_string(i) + "]";
    if (!e.is_number())
      fail(at + " = " + shown_json(e) + ": expected a number" + in + ", got " + article(e));
    const double d = e.get<double>();
    if (!std::isfinite(d)) fail(at + " = " + format_number(d) + ": must be a finite number" + in);
    out.push_back(d);
  }
  return out;
}

}  // namespace bearing::json_document
