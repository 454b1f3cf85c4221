// sweep.csv's columns after the keys, status and error, and a row's fields in them.

#include "bearing/sweep_columns.h"

#include <charconv>

#include "bearing/choice.h"

namespace bearing {

namespace {

constexpr const char* kChannelFields[] = {"rms",       "ptp", "kurtosis", "crest", "peak_frequency",
                                          "peak_label"};
constexpr const char* kMicrophoneFields[] = {"spl_total", "spl_ring", "spl_balls"};
constexpr const char* kEnvelopeFields[] = {"band_low",        "band_high",      "spectral_kurtosis",
                                           "energy_fraction", "peak_frequency", "peak_amplitude",
                                           "peak_label"};
constexpr const char* kDiagnosisFields[] = {"family",
                                            "channel",
                                            "spectral_kurtosis",
                                            "family_share",
                                            "evidence_labels",
                                            "evidence_frequencies",
                                            "evidence_amplitudes",
                                            "reason"};
constexpr std::string_view kEnvelopePrefix = "env_";

bool ends_with(std::string_view s, std::string_view tail) {
  return s.size() > tail.size() && s.substr(s.size() - tail.size()) == tail;
}

SweepCell number(const std::optional<double>& v) {
  return v ? SweepCell(*v) : SweepCell();
}

void add_channel(std::vector<SweepCell>& cells, const ChannelSummary* ch) {
  if (!ch) {
    cells.resize(cells.size() + std::size(kChannelFields));
    return;
  }
  const ChannelStatistics& s = ch->statistics;
  for (double v : {s.rms, s.ptp, s.kurtosis, s.crest}) cells.emplace_back(v);
  const Peak* peak = ch->peaks.empty() ? nullptr : &ch->peaks.front();
  cells.push_back(peak ? SweepCell(peak->frequency) : SweepCell());
  cells.emplace_back(peak ? peak->label : std::string());
}

void add_envelope(std::vector<SweepCell>& cells, const SweepEnvelope* e) {
  if (!e) {
    cells.resize(cells.size() + std::size(kEnvelopeFields));
    return;
  }
  for (double v : {e->band.low, e->band.high, e->spectral_kurtosis}) cells.emplace_back(v);
  cells.push_back(number(e->energy_fraction));
  cells.push_back(e->peak ? SweepCell(e->peak->frequency) : SweepCell());
  cells.push_back(e->peak ? SweepCell(e->peak->amplitude) : SweepCell());
  cells.emplace_back(e->peak ? e->peak->label : std::string());
}

// "BPFO;2xBPFO" or "107.4;214.8": one field of each evidence line.
template <class Field>
std::string joined(const std::vector<Peak>& lines, Field field) {
  std::string out;
  for (const Peak& p : lines) {
    if (!out.empty()) out += ';';
    field(out, p);
  }
  return out;
}

void add_diagnosis(std::vector<SweepCell>& cells, const Diagnosis* d) {
  if (!d) {
    cells.resize(cells.size() + std::size(kDiagnosisFields));
    return;
  }
  cells.emplace_back(std::string(name_of(kFaultFamilies, d->family)));
  cells.emplace_back(d->channel);
  cells.emplace_back(d->spectral_kurtosis);
  cells.emplace_back(d->family_share);
  cells.emplace_back(joined(d->evidence, [](std::string& o, const Peak& p) { o += p.label; }));
  cells.emplace_back(
      joined(d->evidence, [](std::string& o, const Peak& p) { append_number(o, p.frequency); }));
  cells.emplace_back(
      joined(d->evidence, [](std::string& o, const Peak& p) { append_number(o, p.amplitude); }));
  cells.emplace_back(d->reason);
}

}  // namespace

void append_number(std::string& out, double v) {
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, res.ptr);
}

SweepColumns sweep_columns(const SweepRow& first_ok) {
  SweepColumns c;
  for (const auto& ch : first_ok.channels)
    if (ch.group == ChannelGroup::ring) c.channels.push_back(ch.name);
  c.microphones = first_ok.microphones.size();
  for (const auto& e : first_ok.envelopes) c.envelopes.push_back(e.channel);
  c.diagnosis = first_ok.diagnosis.has_value();
  return c;
}

// Each group's first field marks it: `<ch>.rms`, `mic<i>.spl_total`, `env_<ch>.band_low`,
// `diagnosis.family`.
SweepColumns sweep_columns(std::string_view header) {
  SweepColumns c;
  const std::string_view rms = ".rms", spl = ".spl_total", band = ".band_low";
  for (std::size_t start = 0;;) {
    const auto comma = header.find(',', start);
    const std::string_view field = header.substr(start, comma - start);
    if (field.substr(0, kEnvelopePrefix.size()) == kEnvelopePrefix && ends_with(field, band))
      c.envelopes.emplace_back(field.substr(kEnvelopePrefix.size(),
                                            field.size() - kEnvelopePrefix.size() - band.size()));
    else if (ends_with(field, rms))
      c.channels.emplace_back(field.substr(0, field.size() - rms.size()));
    else if (ends_with(field, spl))
      ++c.microphones;
    else if (field == "diagnosis.family")
      c.diagnosis = true;
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return c;
}

std::vector<std::string> sweep_column_names(const SweepColumns& columns) {
  std::vector<std::string> names;
  for (const auto& ch : columns.channels)
    for (const char* f : kChannelFields) names.push_back(ch + "." + f);
  for (std::size_t i = 1; i <= columns.microphones; ++i)
    for (const char* f : kMicrophoneFields) names.push_back("mic" + std::to_string(i) + "." + f);
  for (const auto& ch : columns.envelopes)
    for (const char* f : kEnvelopeFields)
      names.push_back(std::string(kEnvelopePrefix) + ch + "." + f);
  if (columns.diagnosis)
    for (const char* f : kDiagnosisFields) names.push_back(std::string("diagnosis.") + f);
  return names;
}

std::vector<SweepCell> sweep_cells(const SweepColumns& columns, const SweepRow& row) {
  std::vector<SweepCell> cells;
  for (const auto& name : columns.channels) {
    const ChannelSummary* ch = nullptr;
    for (const auto& c : row.channels)
      if (c.name == name) ch = &c;
    add_channel(cells, ch);
  }
  for (std::size_t i = 0; i < columns.microphones; ++i) {
    const MicrophoneLevels* m = i < row.microphones.size() ? &row.microphones[i] : nullptr;
    for (const std::optional<double>* v :
         {m ? &m->spl_total : nullptr, m ? &m->spl_ring : nullptr, m ? &m->spl_balls : nullptr})
      cells.push_back(v ? number(*v) : SweepCell());
  }
  for (const auto& name : columns.envelopes) {
    const SweepEnvelope* e = nullptr;
    for (const auto& x : row.envelopes)
      if (x.channel == name) e = &x;
    add_envelope(cells, e);
  }
  if (columns.diagnosis) add_diagnosis(cells, row.diagnosis ? &*row.diagnosis : nullptr);
  return cells;
}

}  // namespace bearing
