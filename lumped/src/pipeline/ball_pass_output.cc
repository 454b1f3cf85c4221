// The ball-pass stiffness in the outputs (ball_pass_output.h).

#include "bearing/ball_pass_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace bearing {

const char* const kBallPassDefinition =
    "K at `samples` cage angles phi_k = phi_0 + k (2 pi/Z)/N, k = 0 ... N-1, through one ball "
    "pitch from the case's cage phase phi_0 (cage_angles[0]: the case's cage angle, of "
    "stiffness_at_cage_angle), each its own equilibrium under the point's load; mean, min and "
    "max entry by entry (the mean is rotor.stiffness, what a rotor model takes); harmonics[m-1] "
    "the amplitude of each entry at m x BPFO, (2/N) |sum_k K_k exp(-2 pi i m k/N)|, "
    "every m < N/2: in time K(t) = mean + sum_m amplitude_m cos(2 pi m BPFO t + phase_m), "
    "the parametric excitation the dynamic models feel";

namespace {

std::string harmonic_name(std::size_t m) {
  return std::to_string(m) + "xBPFO";
}

const BallPassStiffness& ball_pass_of(const StiffnessRow& r) {
  if (!r.point.ball_pass) throw std::logic_error("ball-pass output of a point without one");
  return *r.point.ball_pass;
}

std::string num(double v, int digits = 4) {
  if (v == 0) v = 0;  // no "-0"
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string pad(const std::string& s, std::size_t width) {
  return s.size() >= width ? s : std::string(width - s.size(), ' ') + s;
}

// A diagonal term at round-off of the largest diagonal term of its unit over the pitch (e.g.
// k_xx = 1e-9 N/m beside k_yy = 1e8 N/m, or the harmonics of a ripple-free axial load) shows as 0.
double shown(double v, const BallPassStiffness& b, int i) {
  double scale = 0;
  for (int j = 0; j < 5; ++j)
    if ((j >= 3) == (i >= 3)) scale = std::max(scale, std::fabs(b.max(j, j)));
  return std::fabs(v) <= 1e-12 * scale ? 0.0 : v;
}

}  // namespace

nlohmann::json ball_pass_json(const StiffnessPoint& p) {
  using nlohmann::json;
  if (!p.ball_pass) throw std::logic_error("ball_pass_json of a point without a ball pass");
  const BallPassStiffness& b = *p.ball_pass;
  json harmonics = json::array();
  for (std::size_t m = 1; m <= b.harmonics.size(); ++m)
    harmonics.push_back({{"order", m},
                         {"frequency", static_cast<double>(m) * p.bpfo},
                         {"amplitude", stiffness_matrix_json(b.harmonics[m - 1])}});
  return {{"samples", b.samples.size()},
          {"cage_angles", b.cage_angles},
          {"bpfo", p.bpfo},
          {"mean", stiffness_matrix_json(b.mean)},
          {"min", stiffness_matrix_json(b.min)},
          {"max", stiffness_matrix_json(b.max)},
          {"harmonics", harmonics}};
}

nlohmann::json ball_pass_units_json(const std::string& k_units) {
  const std::string k = k_units + ", entry by entry";
  return {{"ball_pass.cage_angles", "rad"},
          {"ball_pass.bpfo", "Hz"},
          {"ball_pass.mean", k},
          {"ball_pass.min", k},
          {"ball_pass.max", k},
          {"ball_pass.harmonics.frequency", "Hz"},
          {"ball_pass.harmonics.amplitude", k}};
}

std::string ball_pass_csv(const StiffnessTable& t) {
  if (t.ball_pass_samples <= 0) throw std::logic_error("ball_pass_csv without a ball pass");
  std::ostringstream o;
  std::vector<std::string> header;
  for (const auto& k : t.keys)
    header.push_back(k.key + " [" + (k.unit.empty() ? "-" : k.unit) + "]");
  for (const char* c : {"bpfo [Hz]", "entry", "unit", "at_cage_angle", "mean", "min", "max"})
    header.push_back(c);
  const std::size_t harmonics = static_cast<std::size_t>((t.ball_pass_samples - 1) / 2);
  for (std::size_t m = 1; m <= harmonics; ++m) header.push_back(harmonic_name(m));
  for (std::size_t c = 0; c < header.size(); ++c) o << (c ? "," : "") << header[c];
  o << "\n";
  for (const StiffnessRow& r : t.rows) {
    const BallPassStiffness& b = ball_pass_of(r);
    if (b.harmonics.size() != harmonics)
      throw std::logic_error("ball_pass_csv: a point with another sample count");
    std::string point;  // the cells every row of this point starts with
    for (double v : r.values) point += stiffness_number(v) + ",";
    point += stiffness_number(r.point.bpfo);
    for (int i = 0; i < 5; ++i)
      for (int j = i; j < 5; ++j) {
        o << point << "," << stiffness_name(i, j) << "," << stiffness_unit(i, j) << ","
          << stiffness_number(r.point.solution.at.stiffness(i, j)) << ","
          << stiffness_number(b.mean(i, j)) << "," << stiffness_number(b.min(i, j)) << ","
          << stiffness_number(b.max(i, j));
        for (const Matrix5& h : b.harmonics) o << "," << stiffness_number(h(i, j));
        o << "\n";
      }
  }
  return o.str();
}

std::string ball_pass_text(const StiffnessTable& t) {
  if (t.ball_pass_samples <= 0) return "";
  std::ostringstream o;
  o << "\nOver one ball pass: the range, the mean (the rotor's) and the amplitude at 1xBPFO ("
    << t.ball_pass_samples
    << " cage angles through a pitch, each its own equilibrium under the point's load;\nevery "
       "term and harmonic: stiffness_ball_pass.csv)\n";
  // The leading columns (the varied keys, the BPFO), then a group of three per term under its
  // name and unit, so that each column stays narrow.
  std::vector<std::string> head;
  for (const auto& k : t.keys) head.push_back(k.key + " [" + (k.unit.empty() ? "-" : k.unit) + "]");
  head.push_back("BPFO [Hz]");
  std::vector<std::size_t> width;
  for (const auto& h : head) width.push_back(std::max<std::size_t>(h.size() + 2, 11));
  constexpr std::size_t kColumn = 10, kGap = 3;
  std::string groups, columns;
  for (std::size_t c = 0; c < head.size(); ++c) {
    groups += std::string(width[c], ' ');
    columns += pad(head[c], width[c]);
  }
  for (const char* term : {"k_xx [N/m]", "k_yy [N/m]", "k_zz [N/m]"}) {
    const std::string name = term;
    groups += std::string(kGap, ' ') + name + std::string(4 * kColumn - name.size(), ' ');
    columns += std::string(kGap, ' ') + pad("min", kColumn) + pad("mean", kColumn) +
               pad("max", kColumn) + pad("1xBPFO", kColumn);
  }
  while (!groups.empty() && groups.back() == ' ') groups.pop_back();
  o << groups << "\n" << columns << "\n";
  for (const StiffnessRow& r : t.rows) {
    const BallPassStiffness& b = ball_pass_of(r);
    std::size_t c = 0;
    for (double v : r.values) o << pad(num(v, 5), width[c++]);
    o << pad(num(r.point.bpfo, 5), width[c]);
    for (int i = 0; i < 3; ++i)
      o << std::string(kGap, ' ') << pad(num(shown(b.min(i, i), b, i)), kColumn)
        << pad(num(shown(b.mean(i, i), b, i)), kColumn)
        << pad(num(shown(b.max(i, i), b, i)), kColumn)
        << pad(num(shown(b.harmonics.front()(i, i), b, i)), kColumn);
    o << "\n";
  }
  return o.str();
}

std::string ball_pass_diagonal_text(const StiffnessPoint& p, const std::string& indent) {
  if (!p.ball_pass) return "";
  const BallPassStiffness& b = *p.ball_pass;
  std::ostringstream o;
  o << indent << "over one ball pass (" << b.samples.size()
    << " cage angles through a pitch, each its own equilibrium under this load; BPFO = "
    << num(p.bpfo, 5) << " Hz), the diagonal:\n"
    << indent << pad("", 20) << pad("min", 12) << pad("max", 12) << pad("1xBPFO", 12) << "\n";
  for (int i = 0; i < 5; ++i) {
    const std::string name = stiffness_name(i, i) + " [" + stiffness_unit(i, i) + "]";
    o << indent << name << std::string(name.size() < 20 ? 20 - name.size() : 1, ' ')
      << pad(num(shown(b.min(i, i), b, i)), 12) << pad(num(shown(b.max(i, i), b, i)), 12)
      << pad(num(shown(b.harmonics.front()(i, i), b, i)), 12) << "\n";
  }
  return o.str();
}

}  // namespace bearing
