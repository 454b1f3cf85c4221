#include "report.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "bearing/errors.h"

namespace bearing::verify {

namespace fs = std::filesystem;

const char* to_string(Status s) {
  switch (s) {
    case Status::pass:
      return "pass";
    case Status::fail:
      return "fail";
    case Status::skipped:
      return "skipped";
    case Status::reported:
      return "reported";
  }
  return "?";
}

const char* to_string(ReferenceKind k) {
  switch (k) {
    case ReferenceKind::closed_form:
      return "closed-form";
    case ReferenceKind::fe:
      return "fe";
    case ReferenceKind::convergence:
      return "convergence";
    case ReferenceKind::conservation:
      return "conservation";
    case ReferenceKind::limit:
      return "limit";
    case ReferenceKind::cross_model:
      return "cross-model";
    case ReferenceKind::paper:
      return "paper";
    case ReferenceKind::measurement:
      return "measurement";
    case ReferenceKind::unit_test:
      return "unit-test";
  }
  return "?";
}

const char* to_string(Level l) {
  switch (l) {
    case Level::quick:
      return "quick";
    case Level::standard:
      return "standard";
    case Level::full:
      return "full";
  }
  return "?";
}

namespace {

// Checks with status `s`; a pass counts as passed (derived bound) or pinned (regression pin).
int count(const Report& r, Status s, bool pinned = false) {
  int n = 0;
  for (const auto& c : r.results)
    n += c.status == s && (s != Status::pass ||
                           (c.check->tolerance.basis == Tolerance::Basis::pin) == pinned)
             ? 1
             : 0;
  return n;
}

// Writes `text` to `path` through a temporary file, so the file is complete or absent.
void write_file(const fs::path& path, const std::string& text) {
  const fs::path tmp = path.string() + ".partial";
  {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    if (!out) throw InputError("--out: cannot write " + path.string());
  }
  fs::rename(tmp, path);
}

}  // namespace

int Report::failed() const {
  return count(*this, Status::fail);
}
int Report::passed() const {
  return count(*this, Status::pass);
}
int Report::skipped() const {
  return count(*this, Status::skipped);
}
int Report::reported() const {
  return count(*this, Status::reported);
}
int Report::pinned() const {
  return count(*this, Status::pass, true);
}

void write_report(const Report& report, const std::string& dir, const std::string& plot_script) {
  const fs::path out(dir);
  const fs::path figures = out / "figures";
  // A report folder used before holds only this report: no stale page, data or figure.
  fs::remove_all(figures);
  fs::create_directories(figures);
  for (const char* name : {"report.html", "report.md", "report.json"}) fs::remove(out / name);
  write_figures(report, figures.string(), plot_script);
  write_file(out / "report.json", report_json(report).dump(1) + "\n");
  write_file(out / "report.md", report_markdown(report));
  write_file(out / "report.html", report_html(report, figures.string()));
}

}  // namespace bearing::verify
