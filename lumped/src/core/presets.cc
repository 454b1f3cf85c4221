#include "bearing/presets.h"

#include <map>

#include "bearing/errors.h"

namespace bearing {

namespace {

constexpr double mm = 1e-3;
constexpr double um = 1e-6;

struct Entry {
  Bearing bearing;
  std::string source;
};

// Steel used where a paper gives no material: Harris's E = 208 GPa, ν = 0.3 (the values behind
// his δ = 2.79e-4 δ* Q^{2/3} Σρ^{1/3} shortcut, seed 001 eq. 2.10), density 7850 kg/m³.
Material steel(double young = 2.08e11) {
  return Material{young, 0.3, 7850.0};
}

Bearing make(const char* name, double D, double dm, int Z, double fi, double fo, double Pd,
             Material m) {
  Bearing b;
  b.designation = name;
  b.ball_diameter = D;
  b.pitch_diameter = dm;
  b.balls = Z;
  b.inner_conformity = fi;
  b.outer_conformity = fo;
  b.clearance = Pd;
  b.contact_angle = 0.0;
  b.ball = m;
  b.rings = m;
  return b;
}

const std::map<std::string, Entry>& catalogue() {
  static const std::map<std::string, Entry> entries = [] {
    std::map<std::string, Entry> e;

    // 608 — seed 000 (000_cdf0d0dc9304cb03.txt) Table 1: Z = 7, D_w = 3.969 mm, groove radii
    // r_i = 2.044 mm, r_o = 2.084 mm, raceway diameters F = 11.58 mm, E = 19.52 mm, clearance
    // 0.005 mm. d_m = (F + E)/2 = 15.55 mm. The raceway diameters are rounded to 0.01 mm, so the
    // clearance is taken from the table, not from E − F − 2 D_w. No material given: steel.
    e["608"] = {make("608", 3.969 * mm, 0.5 * (11.58 + 19.52) * mm, 7, 2.044 / 3.969, 2.084 / 3.969,
                     5 * um, steel()),
                "seed 000 (Zhang, Yang, An 2018) Table 1; steel E = 208 GPa assumed"};

    // 6304 — seed 004 (004_b94dc03abe73aeae.txt) Table 1: d_o = 45.538 mm, d_i = 26.475 mm,
    // d_m = 36 mm, D = 9.525 mm, Z = 7, P_d = 15 µm, α = 0, E = 2.07e11 Pa, ν = 0.3. The paper
    // gives no groove radii: f = 0.52 assumed (Harris's typical deep-groove conformity).
    e["6304"] = {make("6304", 9.525 * mm, 36.0 * mm, 7, 0.52, 0.52, 15 * um, steel(2.07e11)),
                 "seed 004 Table 1 (SKF 6304); conformity 0.52 assumed (not in the paper)"};

    // 6308 — seed 003 (003_790048304106e649.txt) Table 1: D = 15.081 mm, d_m = 65 mm, Z = 8, α = 0.
    // The table swaps the raceway labels ("inner 80.088 mm, outer 49.912 mm"): put right, the inner
    // raceway is 49.912 mm and the outer 80.088 mm, so P_d = d_o − d_i − 2D = 14 µm. No groove
    // radii or material given: f = 0.52 and steel assumed.
    {
      const double d_i = 49.912 * mm, d_o = 80.088 * mm, D = 15.081 * mm;
      e["6308"] = {make("6308", D, 65.0 * mm, 8, 0.52, 0.52, d_o - d_i - 2 * D, steel()),
                   "seed 003 Table 1 (raceway diameters un-swapped: d_i 49.912 mm, d_o 80.088 mm); "
                   "conformity 0.52 and steel assumed"};
    }

    // 6205 — SKF 6205 as used in the Case Western Reserve University bearing data: D = 0.3126 in
    // (7.940 mm), d_m = 1.537 in (39.04 mm), Z = 9. Conformity 0.52 assumed; clearance 12.5 µm,
    // the middle of ISO 5753-1 group N for a 25 mm bore (5–20 µm).
    e["6205"] = {
        make("6205", 0.3126 * 25.4 * mm, 1.537 * 25.4 * mm, 9, 0.52, 0.52, 12.5 * um, steel()),
        "SKF 6205 (CWRU data: D 0.3126 in, d_m 1.537 in, Z 9); conformity 0.52 and "
        "clearance 12.5 um (ISO 5753 group N mid) assumed"};

    // 6203 — SKF 6203-2RS JEM, the fan-end bearing of the CWRU data (tests/data/cwru/fan_end/):
    // D = 0.2656 in (6.746 mm), d_m = 1.122 in (28.50 mm), Z = 8, contact angle 0, as the data set
    // publishes them. Its published defect frequencies (× f_r: BPFI 4.9469, BPFO 3.0530, FTF
    // 0.3817, ball 3.9900) are this geometry's to 0.004 %, 0.016 % and 0.06 % (BPFO, FTF, 2·BSF:
    // 3.0531, 0.38164, 3.9877), BPFI to its digits. Conformity 0.52 assumed (not published); clearance 10.5 µm, the middle
    // of ISO 5753-1 group N for a 17 mm bore (3–18 µm).
    e["6203"] = {
        make("6203", 0.2656 * 25.4 * mm, 1.122 * 25.4 * mm, 8, 0.52, 0.52, 10.5 * um, steel()),
        "SKF 6203 (CWRU fan-end data: D 0.2656 in, d_m 1.122 in, Z 8); conformity 0.52 and "
        "clearance 10.5 um (ISO 5753 group N mid) assumed"};

    // 209 — Harris, Rolling Bearing Analysis, the 209 deep-groove ball bearing of his worked
    // examples: D = 12.7 mm, d_i = 52.291 mm, d_o = 77.706 mm (d_m = 65 mm), Z = 9,
    // f_i = f_o = 0.52, P_d = 0.015 mm, steel.
    {
      const double d_i = 52.291 * mm, d_o = 77.706 * mm, D = 12.7 * mm;
      e["209"] = {make("209", D, 0.5 * (d_i + d_o), 9, 0.52, 0.52, d_o - d_i - 2 * D, steel()),
                  "Harris, Rolling Bearing Analysis: 209 deep-groove example (d_i 52.291 mm, "
                  "d_o 77.706 mm, D 12.7 mm, Z 9, f 0.52)"};
    }
    return e;
  }();
  return entries;
}

}  // namespace

Bearing preset(const std::string& designation) {
  const auto& c = catalogue();
  const auto it = c.find(designation);
  if (it == c.end()) {
    std::string known;
    for (const auto& name : preset_names()) known += (known.empty() ? "" : ", ") + name;
    throw InputError("bearing.preset = \"" + designation +
                     "\": unknown bearing; known presets: " + known);
  }
  return it->second.bearing;
}

std::vector<std::string> preset_names() {
  return {"608", "6304", "6308", "6205", "6203", "209"};
}

std::string preset_source(const std::string& designation) {
  const auto& c = catalogue();
  const auto it = c.find(designation);
  return it == c.end() ? std::string() : it->second.source;
}

}  // namespace bearing
