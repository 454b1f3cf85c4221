#include "bearing/records/csv_record.h"

#include <charconv>
#include <cmath>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "bearing/records/channel_choice.h"
#include "bearing/records/time_column.h"
#include "bearing/units.h"
#include "file_bytes.h"

namespace bearing {

namespace {

struct Line {
  std::size_t number;  // from 1
  std::string_view text;
};

std::string_view trim(std::string_view s) {
  const auto space = [](char c) { return c == ' ' || c == '\t'; };
  while (!s.empty() && space(s.front())) s.remove_prefix(1);
  while (!s.empty() && space(s.back())) s.remove_suffix(1);
  return s;
}

// The lines that hold something, with their numbers; a '#' line is a comment.
std::vector<Line> lines_of(std::string_view text) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  std::vector<Line> out;
  std::size_t number = 0;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    ++number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (!trim(line).empty()) out.push_back({number, line});
  }
  return out;
}

bool is_comment(const Line& l) {
  return trim(l.text).front() == '#';
}

// ',' ';' or tab, whichever the first content line has outside quotes, in this order; 0: runs
// of spaces.
char delimiter_of(std::string_view line) {
  std::string outside;
  bool quoted = false;
  for (const char c : line) {
    if (c == '"')
      quoted = !quoted;
    else if (!quoted)
      outside += c;
  }
  for (const char d : {',', ';', '\t'})
    if (outside.find(d) != std::string::npos) return d;
  return 0;
}

// The fields of a line: split at `delim` outside double quotes, trimmed, quotes removed ("" is a
// quote inside them). With delim 0, runs of spaces and tabs separate.
std::vector<std::string> fields_of(std::string_view line, char delim) {
  std::vector<std::string> out;
  if (delim == 0) {
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
      const std::size_t start = i;
      while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
      if (i == start) continue;
      const std::string_view token = line.substr(start, i - start);
      // "DE [g]": a unit in brackets belongs to the name before it.
      if (!out.empty() && (token.front() == '[' || token.front() == '('))
        out.back() += " " + std::string(token);
      else
        out.emplace_back(token);
    }
    return out;
  }
  std::string field;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '"') {
      if (quoted && i + 1 < line.size() && line[i + 1] == '"') {
        field += '"';
        ++i;
      } else {
        quoted = !quoted;
      }
    } else if (c == delim && !quoted) {
      out.emplace_back(trim(field));
      field.clear();
    } else {
      field += c;
    }
  }
  out.emplace_back(trim(field));
  return out;
}

// A number as C writes it (a leading '+' allowed), and the place value of its last digit.
struct Number {
  double value;
  double quantum;
};

std::optional<Number> number_of(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  // Place value: decimals after '.', shifted by the exponent (0.000083 → 1e-6, 8.3e-5 → 1e-6).
  const std::size_t dot = s.find('.');
  const std::size_t e = s.find_first_of("eE");
  long exponent = 0;
  if (e != std::string_view::npos) {
    std::string_view x = s.substr(e + 1);
    if (!x.empty() && x.front() == '+') x.remove_prefix(1);
    if (std::from_chars(x.data(), x.data() + x.size(), exponent).ec != std::errc()) exponent = 0;
  }
  long decimals = 0;
  if (dot != std::string_view::npos)
    decimals = static_cast<long>((e == std::string_view::npos ? s.size() : e) - dot - 1);
  return Number{v, std::pow(10.0, static_cast<double>(exponent - decimals))};
}

bool all_numbers(const std::vector<std::string>& fields) {
  for (const std::string& f : fields)
    if (!number_of(f)) return false;
  return true;
}

// A header cell "DE [g]" or "DE (g)": the name and the unit ("" when none).
std::pair<std::string, std::string> name_and_unit(const std::string& cell) {
  for (const auto& [open, close] : {std::pair{'[', ']'}, std::pair{'(', ')'}}) {
    const std::size_t o = cell.rfind(open);
    if (!cell.empty() && cell.back() == close && o != std::string::npos && o > 0)
      return {std::string(trim(std::string_view(cell).substr(0, o))),
              std::string(trim(std::string_view(cell).substr(o + 1, cell.size() - o - 2)))};
  }
  return {cell, ""};
}

struct Header {
  std::vector<std::string> names;  // one per column
  std::vector<std::string> units;  // "" where the header states none
  std::size_t first_data = 0;      // index in the lines of the first data line
};

Header header_of(const std::vector<Line>& lines, char delim, const std::string& file) {
  Header h;
  std::size_t i = 0;
  while (i < lines.size() && is_comment(lines[i])) ++i;
  if (i == lines.size()) throw record_error(file, "", "no samples: the file has no data line");
  std::vector<std::string> first = fields_of(lines[i].text, delim);
  std::vector<std::string> cells;
  if (!all_numbers(first)) {
    cells = std::move(first);
    h.first_data = i + 1;
  } else {
    h.first_data = i;
    // numpy.savetxt's header: "# t,DE" right before the data, with as many fields.
    if (i > 0 && is_comment(lines[i - 1])) {
      std::string_view c = trim(lines[i - 1].text);
      c.remove_prefix(1);
      std::vector<std::string> f = fields_of(trim(c), delim);
      if (f.size() == first.size() && !all_numbers(f)) cells = std::move(f);
    }
    if (cells.empty())
      for (std::size_t k = 0; k < first.size(); ++k) cells.push_back(std::to_string(k));
  }
  std::set<std::string> seen;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    auto [name, unit] = name_and_unit(cells[k]);
    if (name.empty())
      throw record_error(file, "", "column " + std::to_string(k) + " of the header has no name");
    if (!seen.insert(name).second)
      throw record_error(file, "", "two columns of the header are named " + name);
    h.names.push_back(std::move(name));
    h.units.push_back(std::move(unit));
  }
  return h;
}

std::optional<std::size_t> time_column_of(const Header& h, const std::string& file) {
  std::optional<std::size_t> found;
  for (std::size_t k = 0; k < h.names.size(); ++k) {
    if (!is_time_column_name(h.names[k])) continue;
    if (found)
      throw record_error(
          file, "", "two time columns, " + h.names[*found] + " and " + h.names[k] + ": keep one");
    if (!h.units[k].empty() && h.units[k] != "s")
      throw record_error(
          file, "", "time column " + h.names[k] + " is in " + h.units[k] + ": it must be in s");
    found = k;
  }
  return found;
}

}  // namespace

RawChannel parse_csv_record(std::string_view text, const std::string& file,
                            const RecordOptions& options) {
  const std::vector<Line> lines = lines_of(text);
  std::size_t first_content = 0;
  while (first_content < lines.size() && is_comment(lines[first_content])) ++first_content;
  const char delim = first_content < lines.size() ? delimiter_of(lines[first_content].text) : ',';
  const Header h = header_of(lines, delim, file);
  const std::optional<std::size_t> time = time_column_of(h, file);

  std::vector<std::string> candidates;
  std::vector<std::size_t> column_of;
  for (std::size_t k = 0; k < h.names.size(); ++k)
    if (k != time) {
      candidates.push_back(h.names[k]);
      column_of.push_back(k);
    }
  const std::size_t column = column_of[choose_channel(candidates, options, file, "column")];

  RawChannel raw;
  raw.channel = h.names[column];
  if (!h.units[column].empty()) {
    raw.unit = h.units[column];
    raw.unit_origin = "the header of column " + raw.channel;
  }
  std::vector<double> t, quantum;
  for (std::size_t i = h.first_data; i < lines.size(); ++i) {
    if (is_comment(lines[i])) continue;
    const std::vector<std::string> f = fields_of(lines[i].text, delim);
    const std::string at = "line " + std::to_string(lines[i].number);
    if (f.size() != h.names.size())
      throw record_error(file, raw.channel,
                         at + " has " + std::to_string(f.size()) + " fields, the header " +
                             std::to_string(h.names.size()));
    const auto number = [&](std::size_t k) {
      const std::optional<Number> n = number_of(f[k]);
      if (!n || !std::isfinite(n->value))
        throw record_error(
            file, raw.channel,
            at + ", column " + h.names[k] + ": \"" + f[k] + "\" is not a finite number");
      return *n;
    };
    raw.values.push_back(number(column).value);
    if (time) {
      const Number n = number(*time);
      t.push_back(n.value);
      quantum.push_back(n.quantum);
    }
  }
  if (time && !raw.values.empty()) {
    const TimeColumnRate r = time_column_rate(t, quantum, file, raw.channel, h.names[*time]);
    raw.rate = r.rate;
    raw.rate_tolerance = r.tolerance;
    raw.rate_origin = "time column " + h.names[*time];
  }
  return raw;
}

RawChannel read_csv_record(const std::filesystem::path& file, const RecordOptions& options) {
  return parse_csv_record(records_detail::file_bytes(file), file.string(), options);
}

}  // namespace bearing
