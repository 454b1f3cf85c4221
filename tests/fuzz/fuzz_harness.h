#pragma once
// What every fuzz harness shares: the documented error model. Bad input throws
// bearing::InputError and is fine; any other exception escaping a parser is a bug, so it is
// reported and turned into a crash that libFuzzer (or the replay driver) records.

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "bearing/errors.h"

namespace bearing::fuzz {

/// Runs `body`; InputError is the documented answer to bad input, anything else aborts.
template <class Body>
void expect_only_input_errors(const char* target, Body&& body) {
  try {
    body();
  } catch (const InputError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: an exception other than InputError escaped: %s\n", target, e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "%s: a non-standard exception escaped\n", target);
    std::abort();
  }
}

/// A property the parser documents did not hold: report it and crash.
[[noreturn]] inline void property_failed(const char* target, const std::string& what) {
  std::fprintf(stderr, "%s: %s\n", target, what.c_str());
  std::abort();
}

}  // namespace bearing::fuzz
