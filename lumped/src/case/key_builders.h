#pragma once
// Private to the case schema: the row makers. A row's `at` is a generic lambda returning a
// reference to where the value lands, `[](auto& c) -> auto& { return c.rotor.mass; }`, so one
// accessor serves reading (Case&) and writing (const Case&).

#include <cstdio>
#include <limits>
#include <string>
#include <utility>

#include "bearing/errors.h"
#include "bearing/limits.h"
#include "case_schema.h"

namespace bearing::case_schema {

// Ranges of keys only the schema checks; those other layers check too are in bearing/limits.h.
inline Limit positive(const char* allowed) {
  return Limit{nullptr, Dimension::dimensionless, 0, limits::inf, true, false, allowed};
}
inline Limit non_negative(const char* allowed = "must be >= 0") {
  return Limit{nullptr, Dimension::dimensionless, 0, limits::inf, false, false, allowed};
}
inline Limit within(double lo, double hi, bool lo_open, bool hi_open, const char* allowed) {
  return Limit{nullptr, Dimension::dimensionless, lo, hi, lo_open, hi_open, allowed};
}
/// No range check.
inline Limit unchecked() {
  return Limit{nullptr, Dimension::dimensionless, 0, 0, false, false, nullptr};
}
inline bool checked(const Limit& l) {
  return l.allowed != nullptr && *l.allowed != '\0';
}

/// InputError "key = value unit: allowed" unless `ok`.
inline void require(bool ok, const std::string& key, double v, Dimension dim,
                    const std::string& allowed) {
  if (!ok) throw InputError(key + " = " + fmt_si(v, dim) + ": " + allowed);
}

// A shared limit belongs to exactly the key whose row uses it.
inline void require_own_limit(const Limit& limit, const std::string& key) {
  if (limit.key && key != limit.key)
    throw std::logic_error("case schema: row " + key + " uses the limit of " + limit.key);
}

inline void check_limit(const Limit& limit, const std::string& key, double v, Dimension dim) {
  if (!checked(limit) || limit.contains(v)) return;
  if (limit.unit)
    throw InputError(key + " = " + format_quantity(v, limit.unit, dim) + ": " + limit.allowed);
  require(false, key, v, dim, limit.allowed);
}

/// 17 significant digits: the double comes back exactly; TOML needs a float to look like one.
inline std::string num17(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  std::string s = buf;
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

inline std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char ch : s) {
    if (ch == '"' || ch == '\\') out += '\\';
    out += ch;
  }
  return out + "\"";
}

/// A quantity as case.toml writes it: a plain SI number, or "v unit" where a plain number would
/// be ambiguous (angles, angular speeds).
inline std::string quantity_text(double v, Dimension dim) {
  return bare_number_is_si(dim) ? num17(v)
                                : "\"" + num17(v) + " " + std::string(si_unit(dim)) + "\"";
}

inline std::string leaf_of(const std::string& name) {
  return name.substr(name.rfind('.') + 1);
}

inline std::string bool_text(bool v) {
  return v ? "true" : "false";
}

/// A table, with the optional hooks set on the returned row.
inline Key table(std::string name, std::string help) {
  Key k;
  k.name = std::move(name);
  k.kind = Kind::table;
  k.help = std::move(help);
  return k;
}

/// A key only described here (dimension, help): an entry key of an array of tables, or one its
/// table row reads itself.
inline Key described(std::string name, Kind kind, Dimension dim, std::string help) {
  Key k;
  k.name = std::move(name);
  k.kind = kind;
  k.dim = dim;
  k.help = std::move(help);
  return k;
}

/// A number with a dimension; absent, it keeps the Case default or takes `fallback(c)`.
template <class At>
Key quantity(std::string name, Dimension dim, std::string help, At at, Limit limit = unchecked(),
             std::function<double(const Case&)> fallback = {}) {
  Key k = described(std::move(name), Kind::quantity, dim, std::move(help));
  require_own_limit(limit, k.name);
  const std::string leaf = leaf_of(k.name);
  k.read = [at, leaf, fallback](TableReader& r, Case& c, const ReadContext&) {
    if (const auto v = r.quantity(leaf))
      at(c) = *v;
    else if (fallback)
      at(c) = fallback(c);
  };
  if (checked(limit))
    k.check = [at, key = k.name, dim, limit](const Case& c) {
      check_limit(limit, key, at(c), dim);
    };
  k.write = [at, leaf, dim](std::ostream& o, const Case& c) {
    o << leaf << " = " << quantity_text(at(c), dim) << "\n";
  };
  return k;
}

/// A whole number; `limit` is checked on the value as written, before it lands in an int.
template <class At>
Key integer(std::string name, std::string help, At at, Limit limit = unchecked(),
            std::function<int(const Case&)> fallback = {}) {
  Key k = described(std::move(name), Kind::integer, Dimension::dimensionless, std::move(help));
  const std::string leaf = leaf_of(k.name);
  k.read = [at, leaf, limit, fallback, key = k.name](TableReader& r, Case& c, const ReadContext&) {
    if (const auto v = r.integer(leaf)) {
      const bool fits = !checked(limit)
                            ? *v >= -1000000000LL && *v <= 1000000000LL  // no std::abs(LLONG_MIN)
                            : limit.contains(static_cast<double>(*v));
      if (!fits)
        throw InputError(key + " = " + std::to_string(*v) + ": " +
                         (checked(limit) ? limit.allowed : "too large"));
      at(c) = static_cast<int>(*v);
    } else if (fallback) {
      at(c) = fallback(c);
    }
  };
  k.write = [at, leaf](std::ostream& o, const Case& c) { o << leaf << " = " << at(c) << "\n"; };
  return k;
}

template <class At>
Key boolean(std::string name, std::string help, At at) {
  Key k = described(std::move(name), Kind::boolean, Dimension::dimensionless, std::move(help));
  const std::string leaf = leaf_of(k.name);
  k.read = [at, leaf](TableReader& r, Case& c, const ReadContext&) {
    if (const auto v = r.boolean(leaf)) at(c) = *v;
  };
  k.write = [at, leaf](std::ostream& o, const Case& c) {
    o << leaf << " = " << bool_text(at(c)) << "\n";
  };
  return k;
}

/// One name of an enum's table, parsed into the enum here and nowhere else. `what` names the
/// concept in the message ("unknown window; allowed: ...").
template <class E, std::size_t N, class At>
Key choice(std::string name, std::string help, const Named<E> (&names)[N], std::string what,
           At at) {
  Key k = described(std::move(name), Kind::choice, Dimension::dimensionless, std::move(help));
  const std::string leaf = leaf_of(k.name);
  k.read = [at, leaf, &names, what](TableReader& r, Case& c, const ReadContext&) {
    if (const auto v = r.text(leaf)) at(c) = parse_named(names, *v, r.full(leaf), what);
  };
  k.write = [at, leaf, &names](std::ostream& o, const Case& c) {
    o << leaf << " = " << quoted(name_of(names, at(c))) << "\n";
  };
  return k;
}

/// choice() for a key added after case files existed whose default changes no result: the default
/// is not written back, so a case.toml written without the key setting stays byte for byte as
/// before the key existed.
template <class E, std::size_t N, class At>
Key choice_unwritten_at(E fallback, std::string name, std::string help, const Named<E> (&names)[N],
                        std::string what, At at) {
  Key k = choice(std::move(name), std::move(help), names, std::move(what), at);
  const std::string leaf = leaf_of(k.name);
  k.write = [at, leaf, &names, fallback](std::ostream& o, const Case& c) {
    if (at(c) != fallback) o << leaf << " = " << quoted(name_of(names, at(c))) << "\n";
  };
  return k;
}

}  // namespace bearing::case_schema
