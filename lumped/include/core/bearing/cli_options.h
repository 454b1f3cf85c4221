#pragma once
// What the programs' command lines share (bearing-sim, bearing-fem): an option's range, checked
// while the command line is parsed (so before any case is read, run started or mesh built) and
// shown in --help; and the exit status of a command-line error: 2, bad input, with one line on
// stderr, like every other input error (docs/bearing-sim.md, "Exit status").
// Header-only: only the programs, which link CLI11, include it.

#include <cmath>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "bearing/units.h"

namespace bearing::cli {

/// The option's number must lie in [low, high] ((low, high] with `open_low`); NaN never does. The
/// error reads "--degree: 9: must lie in [1, 8]".
inline CLI::Validator range(double low, double high, bool open_low = false) {
  const std::string allowed =
      std::string(open_low ? "(" : "[") + format_number(low) + ", " + format_number(high) + "]";
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        double v = 0;
        std::size_t used = 0;
        try {
          v = std::stod(text, &used);
        } catch (const std::exception&) {
          return text + ": not a number; allowed " + allowed;
        }
        if (used != text.size()) return text + ": not a number; allowed " + allowed;
        const bool above = open_low ? v > low : v >= low;
        if (!(above && v <= high)) return text + ": must lie in " + allowed;
        return {};
      },
      allowed);
}

/// The exit status of a parse error of `app` (the program `program`): --help and --version
/// print and give 0; anything else (an unknown option, a missing or out-of-range value) prints
/// "PROGRAM: error: MESSAGE (see --help)" and gives 2.
inline int parse_error_exit(const CLI::App& app, const CLI::ParseError& e,
                            const std::string& program) {
  if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
  std::cerr << program << ": error: " << e.what() << " (see --help)\n";
  return 2;
}

}  // namespace bearing::cli
