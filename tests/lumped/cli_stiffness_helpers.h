#pragma once
// What the end-to-end tests of `bearing-sim stiffness` share (test_cli_stiffness.cc,
// test_cli_rotor_stiffness.cc): the example case, its 5-DOF solution from the library's own
// pieces, and the CSV and JSON files read back.

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bearing/case_file.h"
#include "bearing/five_dof_static.h"
#include "cli_helpers.h"

namespace bearing::test::stiffness {

namespace fs = std::filesystem;

inline const std::string kExample = std::string(BEARING_SOURCE_DIR) + "/examples/seed003_6308.toml";

// The 5-DOF solution from the library's own pieces, not through the pipeline's mapping: ball 0
// at `phase` [rad] (the example's cage phase is 0).
inline bearing::FiveDofSolution direct(const std::vector<bearing::Override>& sets,
                                       double phase = 0.0) {
  const bearing::Case c = bearing::read_case_file(kExample, sets);
  // ball.centrifugal is on by default: each ball's centrifugal load at the case's speed.
  const bearing::FiveDofBearing b =
      bearing::five_dof_bearing(c.bearing, bearing::contact_constants(c), phase,
                                bearing::ball_centrifugal_load(c.bearing, c.operation.speed));
  bearing::Vector5 f;
  f << c.operation.load.x(), c.operation.load.y(), c.operation.axial_load, c.operation.moment.x(),
      c.operation.moment.y();
  return bearing::solve_five_dof(b, f);
}

inline std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  for (std::string cell; std::getline(s, cell, ',');) out.push_back(cell);
  return out;
}

// stiffness.csv as its header and rows of cells.
struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  double at(std::size_t row, const std::string& column) const {
    for (std::size_t c = 0; c < header.size(); ++c)
      if (header[c] == column) return std::stod(rows.at(row).at(c));
    ADD_FAILURE() << "no column " << column;
    return NAN;
  }
};

inline Csv read_csv(const fs::path& p) {
  std::stringstream s(read(p));
  Csv csv;
  std::string line;
  std::getline(s, line);
  csv.header = split(line);
  while (std::getline(s, line)) csv.rows.push_back(split(line));
  return csv;
}

// K_ij of a JSON 5×5 matrix.
inline double entry(const nlohmann::json& K, int i, int j) {
  return K.at(i).at(j).get<double>();
}

// stiffness_ball_pass.csv as rows of text cells, by column name.
struct LongCsv {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::size_t column(const std::string& name) const {
    for (std::size_t c = 0; c < header.size(); ++c)
      if (header[c] == name) return c;
    ADD_FAILURE() << "no column " << name;
    return 0;
  }
  std::string text(std::size_t row, const std::string& name) const {
    return rows.at(row).at(column(name));
  }
  double at(std::size_t row, const std::string& name) const { return std::stod(text(row, name)); }
};

inline LongCsv read_long_csv(const fs::path& p) {
  const Csv csv = read_csv(p);
  return {csv.header, csv.rows};
}

}  // namespace bearing::test::stiffness
