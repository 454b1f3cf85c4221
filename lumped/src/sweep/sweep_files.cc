// A sweep's folder: the design record, the streamed rows, --resume, --part and merge.

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "bearing/errors.h"
#include "bearing/sweep.h"

namespace bearing {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr const char* kRecord = "sweep.design.json";
constexpr const char* kPartial = ".sweep.csv.partial";
constexpr const char* kFormat = "bearing-sim sweep design 1";

json record_json(const SweepPlan& plan) {
  const auto [first, end] = part_range(plan.design->size(), plan.part);
  json overrides = json::array();
  for (const auto& o : plan.base.overrides) overrides.push_back({o.key, o.value});
  return json{
      {"format", kFormat},
      {"program", plan.program},
      {"design", json::parse(plan.design->json())},
      {"cases", plan.design->size()},
      {"base",
       {{"source", plan.base.source},
        {"text", plan.base.text},
        {"base_dir", plan.base.base_dir},
        {"overrides", overrides},
        {"resolved", case_to_toml(load_sweep_case(plan.base, {}))}}},
      {"part",
       {{"index", plan.part.index}, {"count", plan.part.count}, {"first", first}, {"end", end}}}};
}

json read_record_json(const std::string& dir) {
  const fs::path p = fs::path(dir) / kRecord;
  std::ifstream in(p, std::ios::binary);
  if (!in) throw InputError(p.string() + ": cannot read the sweep's design record");
  try {
    json j = json::parse(in);
    if (j.at("format") != kFormat)
      throw InputError(p.string() + ": not a design record of this bearing-sim (format \"" +
                       j.at("format").get<std::string>() + "\", expected \"" + kFormat + "\")");
    return j;
  } catch (const json::exception& e) {
    throw InputError(p.string() + ": not a sweep design record (" + e.what() + ")");
  }
}

void write_text(const fs::path& path, const std::string& text, const std::string& dir) {
  const fs::path tmp = path.string() + ".tmp";
  std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
  if (!f || !f.write(text.data(), static_cast<std::streamsize>(text.size())) || !f.flush())
    throw InputError("--out " + dir + ": cannot write " + path.filename().string());
  f.close();
  fs::rename(tmp, path);
}

// The status field (after the `keys` value fields) of a row is "ok".
bool row_ok(const std::string& line, std::size_t keys) {
  std::size_t start = 0;
  for (std::size_t k = 0; k < keys; ++k) start = line.find(',', start) + 1;
  return line.compare(start, 3, "ok,") == 0;
}

// The complete lines of a sweep.csv being written: its header, rows (and failed ones) and the
// bytes they take; a last line without its newline (cut by a kill) is not counted.
struct CsvContent {
  std::string header;
  std::size_t rows = 0;
  std::size_t failed = 0;
  std::uintmax_t bytes = 0;
};

CsvContent read_complete_lines(const fs::path& file, std::size_t keys,
                               const std::function<void(const std::string&)>& row = {}) {
  CsvContent c;
  std::ifstream in(file, std::ios::binary);
  std::string line;
  while (std::getline(in, line) && !in.eof()) {
    c.bytes += line.size() + 1;
    if (c.header.empty()) {
      c.header = line;
      continue;
    }
    ++c.rows;
    c.failed += row_ok(line, keys) ? 0 : 1;
    if (row) row(line);
  }
  return c;
}

std::size_t fields(const std::string& line) {
  return static_cast<std::size_t>(std::count(line.begin(), line.end(), ',')) + 1;
}

}  // namespace

SweepBase sweep_base(const std::string& case_path, std::vector<Override> overrides) {
  SweepBase b;
  b.overrides = std::move(overrides);
  if (case_path.empty()) {
    b.source = "built-in default case";
    b.text = default_case_toml();
  } else {
    std::ifstream in(case_path, std::ios::binary);
    if (!in) throw InputError(case_path + ": cannot read the case file");
    std::ostringstream text;
    text << in.rdbuf();
    b.source = case_path;
    b.text = text.str();
    const auto slash = case_path.rfind('/');
    b.base_dir = slash == std::string::npos ? std::string() : case_path.substr(0, slash);
  }
  load_sweep_case(b, {});  // check the base case before starting many runs of it
  return b;
}

Case load_sweep_case(const SweepBase& base, const std::vector<Override>& point) {
  auto all = base.overrides;
  all.insert(all.end(), point.begin(), point.end());
  return parse_case(base.text, base.source, all, base.base_dir);
}

SweepPart parse_part(std::string_view text) {
  const std::string t(text);
  const auto slash = t.find('/');
  SweepPart p{0, 0};
  const auto whole = [&](const std::string& s, std::size_t& v) {
    const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    return !s.empty() && r.ec == std::errc() && r.ptr == s.data() + s.size();
  };
  if (slash == std::string::npos || !whole(t.substr(0, slash), p.index) ||
      !whole(t.substr(slash + 1), p.count) || p.index < 1 || p.index > p.count || p.count > 1000000)
    throw InputError("--part " + t + ": expected K/N with 1 ≤ K ≤ N ≤ 1000000, e.g. --part 3/16");
  return p;
}

std::pair<std::size_t, std::size_t> part_range(std::size_t cases, SweepPart part) {
  // ⌊cases·k/N⌋ without overflow: cases = q·N + r, so it is q·k + ⌊r·k/N⌋ (r·k < N² ≤ 10¹²).
  const auto at = [&](std::size_t k) {
    return cases / part.count * k + cases % part.count * k / part.count;
  };
  return {at(part.index - 1), at(part.index)};
}

std::string sweep_record(const SweepPlan& plan) {
  return record_json(plan).dump(2) + "\n";
}

SweepPlan read_sweep_record(const std::string& dir) {
  const json j = read_record_json(dir);
  SweepPlan plan;
  try {
    plan.design = design_from_json(j.at("design").dump());
    const json& b = j.at("base");
    plan.base.source = b.at("source");
    plan.base.text = b.at("text");
    plan.base.base_dir = b.at("base_dir");
    for (const auto& o : b.at("overrides")) plan.base.overrides.push_back({o.at(0), o.at(1)});
    plan.part = {j.at("part").at("index"), j.at("part").at("count")};
    plan.program = j.at("program");
  } catch (const json::exception& e) {
    throw InputError(dir + "/" + kRecord + ": incomplete design record (" + e.what() + ")");
  }
  return plan;
}

SweepCounts write_sweep(const std::string& dir, const SweepPlan& plan, int threads,
                        const SweepProgress& progress, const SweepRunner& runner, bool resume,
                        const SweepRowHook& hook) {
  if (plan.part.count > plan.design->size())
    throw InputError("--part " + std::to_string(plan.part.index) + "/" +
                     std::to_string(plan.part.count) + ": more parts than the design's " +
                     std::to_string(plan.design->size()) + " cases; use at most " +
                     std::to_string(plan.design->size()) + " parts");
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError("--out " + dir + ": cannot create the folder (" + ec.message() + ")");
  const fs::path file = fs::path(dir) / "sweep.csv", tmp = fs::path(dir) / kPartial;
  const fs::path record = fs::path(dir) / kRecord;
  const SweepDesign& design = *plan.design;
  const auto [first, end] = part_range(design.size(), plan.part);
  SweepCounts counts;
  counts.cases = end - first;
  CsvContent kept;
  const auto cannot_write = [&] { return InputError("--out " + dir + ": cannot write sweep.csv"); };
  try {
    if (resume) {
      kept = read_complete_lines(tmp, design.keys().size());
      if (kept.header.empty()) kept.bytes = 0;
      if (fs::exists(tmp)) fs::resize_file(tmp, kept.bytes);
    } else {
      write_text(record, sweep_record(plan), dir);
    }
    std::ofstream f(tmp, std::ios::binary | (resume ? std::ios::app : std::ios::trunc));
    if (!f) throw cannot_write();
    std::vector<std::string> keys;
    for (const auto& k : design.keys()) keys.push_back(k.key);
    SweepCsvWriter writer(keys, [&](std::string_view s) {
      // Flushed row by row: a killed sweep leaves every finished row for --resume.
      if (!f.write(s.data(), static_cast<std::streamsize>(s.size())) || !f.flush())
        throw cannot_write();
    });
    if (!kept.header.empty()) writer.continue_after(kept.header);
    counts.failed = kept.failed;
    const std::size_t start = first + kept.rows;
    const bool keep = static_cast<bool>(hook.add);
    const std::vector<SweepSave> no_tables;
    const auto run = runner ? runner : SweepRunner([](auto&&... a) { run_sweep(a...); });
    run([&](const std::vector<Override>& point) { return load_sweep_case(plan.base, point); },
        end - start, [&](std::size_t i) { return design.point(start + i); }, threads,
        [&](std::size_t i, SweepRow&& row) {
          counts.failed += row.ok ? 0 : 1;
          if (keep) hook.add(start + i, row);  // first: every row kept for --resume has its tables
          writer.add(row);
        },
        [&](std::size_t done, std::size_t) {
          if (progress) progress(kept.rows + done, counts.cases);
        },
        keep ? hook.save : no_tables);
    writer.finish();
    f.close();
    if (!f) throw cannot_write();
    if (hook.commit) hook.commit();
    fs::rename(tmp, file);
    if (plan.part.count == 1) fs::remove(record);
  } catch (const fs::filesystem_error& e) {
    throw InputError("--out " + dir + ": " + e.what());
  }
  return counts;
}

std::optional<SweepCounts> finished_sweep(const std::string& dir) {
  const fs::path file = fs::path(dir) / "sweep.csv";
  if (!fs::exists(file) || fs::exists(fs::path(dir) / kPartial)) return std::nullopt;
  std::ifstream in(file, std::ios::binary);
  std::string header;
  std::getline(in, header);
  std::size_t keys = 0;  // the fields before `status`
  for (std::size_t start = 0;; ++keys) {
    const auto comma = header.find(',', start);
    if (header.compare(start, comma - start, "status") == 0) break;
    if (comma == std::string::npos) return std::nullopt;  // no status column: not a sweep.csv
    start = comma + 1;
  }
  const CsvContent c = read_complete_lines(file, keys);
  if (fs::exists(fs::path(dir) / kRecord)) {
    const json part = read_record_json(dir).at("part");
    if (c.rows != part.at("end").get<std::size_t>() - part.at("first").get<std::size_t>())
      return std::nullopt;
  }
  return SweepCounts{c.rows, c.failed};
}

SweepCounts resume_sweep(const std::string& dir, int threads, const SweepProgress& progress,
                         const SweepRunner& runner, const SweepRowHook& hook) {
  if (const auto done = finished_sweep(dir)) return *done;
  return write_sweep(dir, read_sweep_record(dir), threads, progress, runner, true, hook);
}

namespace {

// One folder given to merge, with its record.
struct MergePart {
  std::string dir;
  json record;
  std::size_t index = 0, count = 0, first = 0, end = 0;
};

// The folders' records agree but for the part, and the parts are 1 … N of N, each once.
std::vector<MergePart> check_parts(const std::vector<std::string>& dirs) {
  if (dirs.empty()) throw InputError("merge: give the folders of the parts to merge");
  std::vector<MergePart> parts;
  for (const auto& d : dirs) {
    MergePart p{d, read_record_json(d)};
    const json& part = p.record.at("part");
    p.index = part.at("index"), p.count = part.at("count");
    p.first = part.at("first"), p.end = part.at("end");
    const MergePart& ref = parts.empty() ? p : parts.front();
    for (const char* what : {"program", "design", "cases", "base"})
      if (p.record.at(what) != ref.record.at(what))
        throw InputError("merge: " + d + " and " + ref.dir +
                         " are not parts of the same sweep: their " + what + " differ (see " +
                         kRecord + ")");
    if (p.count != ref.count)
      throw InputError("merge: " + d + " is a part of " + std::to_string(p.count) + ", " + ref.dir +
                       " of " + std::to_string(ref.count));
    const bool stopped = fs::exists(fs::path(d) / kPartial);
    if (stopped || !fs::exists(fs::path(d) / "sweep.csv"))
      throw InputError("merge: " + d + ": part " + std::to_string(p.index) + "/" +
                       std::to_string(p.count) + " is not complete (" +
                       (stopped ? "a run into it stopped before its end: " + std::string(kPartial)
                                : std::string("no sweep.csv")) +
                       "); finish it with --resume " + d);
    parts.push_back(std::move(p));
  }
  std::sort(parts.begin(), parts.end(),
            [](const MergePart& a, const MergePart& b) { return a.index < b.index; });
  const std::string n = std::to_string(parts.front().count);
  for (std::size_t k = 0; k < parts.size(); ++k) {
    if (k > 0 && parts[k].index == parts[k - 1].index)
      throw InputError("merge: part " + std::to_string(parts[k].index) + "/" + n +
                       " given twice: " + parts[k - 1].dir + " and " + parts[k].dir);
  }
  for (std::size_t k = 1, at = 0; k <= parts.front().count; ++k) {
    if (at >= parts.size() || parts[at].index != k)
      throw InputError("merge: part " + std::to_string(k) + "/" + n + " is missing");
    ++at;
  }
  return parts;
}

}  // namespace

SweepCounts merge_sweeps(const std::string& out, const std::vector<std::string>& dirs) {
  std::error_code ec;
  for (const auto& d : dirs)
    if (fs::equivalent(out, d, ec))
      throw InputError("merge: OUT " + out + " is one of the parts; write the merge elsewhere");
  const std::vector<MergePart> parts = check_parts(dirs);
  const std::size_t keys =
      design_from_json(parts.front().record.at("design").dump())->keys().size();
  // The header of the whole sweep: that of the first part with a successful row (the longest);
  // a part of failed rows only has the bare one, and its rows get the empty fields of the others.
  std::string header;
  for (const auto& p : parts) {
    std::ifstream in(fs::path(p.dir) / "sweep.csv", std::ios::binary);
    std::string h;
    std::getline(in, h);
    if (fields(h) > keys + 2 && fields(header) > keys + 2 && h != header)
      throw InputError("merge: " + p.dir + "/sweep.csv has other columns than " +
                       parts.front().dir + "/sweep.csv");
    if (fields(h) > fields(header) || header.empty()) header = h;
  }
  fs::create_directories(out, ec);
  if (ec) throw InputError("merge " + out + ": cannot create the folder (" + ec.message() + ")");
  const fs::path tmp = fs::path(out) / kPartial;
  std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
  f << header << "\n";
  SweepCounts counts;
  for (const auto& p : parts) {
    const fs::path file = fs::path(p.dir) / "sweep.csv";
    std::ifstream in(file, std::ios::binary);
    std::string own;
    std::getline(in, own);
    const std::string pad(fields(header) - fields(own), ',');
    const CsvContent c =
        read_complete_lines(file, keys, [&](const std::string& line) { f << line << pad << "\n"; });
    if (c.rows != p.end - p.first)
      throw InputError("merge: " + file.string() + " has " + std::to_string(c.rows) +
                       " rows, but part " + std::to_string(p.index) + " has " +
                       std::to_string(p.end - p.first) + " cases");
    counts.cases += c.rows;
    counts.failed += c.failed;
  }
  f.close();
  if (!f) throw InputError("merge " + out + ": cannot write sweep.csv");
  fs::rename(tmp, fs::path(out) / "sweep.csv");
  return counts;
}

}  // namespace bearing
