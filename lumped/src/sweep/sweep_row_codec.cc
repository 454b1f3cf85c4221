// SweepRow ↔ bytes: a flat little format of fixed-size fields (raw doubles, 64-bit counts) and
// length-prefixed strings, in the order of the structs' members.

#include "bearing/sweep_row_codec.h"

#include <cstdint>
#include <cstring>
#include <memory>
#include <optional>
#include <stdexcept>
#include <type_traits>

namespace bearing {

namespace {

class Writer {
 public:
  explicit Writer(std::string& out) : out_(out) {}
  template <class T>
  void raw(T v) {
    static_assert(std::is_trivially_copyable_v<T>);
    char bytes[sizeof(T)];
    std::memcpy(bytes, &v, sizeof(T));
    out_.append(bytes, sizeof(T));
  }
  void size(std::size_t n) { raw(static_cast<std::uint64_t>(n)); }
  void text(const std::string& s) {
    size(s.size());
    out_.append(s);
  }
  void maybe(const std::optional<double>& v) {
    raw(static_cast<std::uint8_t>(v.has_value()));
    if (v) raw(*v);
  }

 private:
  std::string& out_;
};

class Reader {
 public:
  explicit Reader(std::string_view in) : in_(in) {}
  template <class T>
  T raw() {
    need(sizeof(T));
    T v;
    std::memcpy(&v, in_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return v;
  }
  std::size_t size() {
    const auto n = raw<std::uint64_t>();
    if (n > in_.size() - at_) fail();  // every element takes at least one byte
    return static_cast<std::size_t>(n);
  }
  std::string text() {
    const std::size_t n = size();
    std::string s(in_.substr(at_, n));
    at_ += n;
    return s;
  }
  std::optional<double> maybe() {
    if (raw<std::uint8_t>() == 0) return std::nullopt;
    return raw<double>();
  }
  void finish() const {
    if (at_ != in_.size()) fail();
  }

 private:
  void need(std::size_t n) const {
    if (n > in_.size() - at_) fail();
  }
  [[noreturn]] static void fail() { throw std::runtime_error("sweep row: malformed bytes"); }
  std::string_view in_;
  std::size_t at_ = 0;
};

void encode_peak(Writer& w, const Peak& p) {
  w.raw(p.frequency);
  w.raw(p.amplitude);
  w.text(p.label);
  w.raw(p.label_error);
}

Peak decode_peak(Reader& r) {
  Peak p;
  p.frequency = r.raw<double>();
  p.amplitude = r.raw<double>();
  p.label = r.text();
  p.label_error = r.raw<double>();
  return p;
}

void encode_peaks(Writer& w, const std::vector<Peak>& peaks) {
  w.size(peaks.size());
  for (const Peak& p : peaks) encode_peak(w, p);
}

std::vector<Peak> decode_peaks(Reader& r) {
  std::vector<Peak> peaks(r.size());
  for (Peak& p : peaks) p = decode_peak(r);
  return peaks;
}

void encode_channel(Writer& w, const ChannelSummary& c) {
  w.text(c.name);
  w.text(c.unit);
  w.raw(static_cast<std::int32_t>(c.group));
  const ChannelStatistics& s = c.statistics;
  for (double v : {s.mean, s.rms, s.ptp, s.kurtosis, s.crest}) w.raw(v);
  encode_peaks(w, c.peaks);
}

ChannelSummary decode_channel(Reader& r) {
  ChannelSummary c;
  c.name = r.text();
  c.unit = r.text();
  c.group = static_cast<ChannelGroup>(r.raw<std::int32_t>());
  ChannelStatistics& s = c.statistics;
  for (double* v : {&s.mean, &s.rms, &s.ptp, &s.kurtosis, &s.crest}) *v = r.raw<double>();
  c.peaks = decode_peaks(r);
  return c;
}

void encode_envelope(Writer& w, const SweepEnvelope& e) {
  w.text(e.channel);
  for (double v : {e.band.low, e.band.high, e.spectral_kurtosis}) w.raw(v);
  w.maybe(e.energy_fraction);
  w.raw(static_cast<std::uint8_t>(e.peak.has_value()));
  if (e.peak) encode_peak(w, *e.peak);
}

SweepEnvelope decode_envelope(Reader& r) {
  SweepEnvelope e;
  e.channel = r.text();
  for (double* v : {&e.band.low, &e.band.high, &e.spectral_kurtosis}) *v = r.raw<double>();
  e.energy_fraction = r.maybe();
  if (r.raw<std::uint8_t>() != 0) e.peak = decode_peak(r);
  return e;
}

void encode_diagnosis(Writer& w, const std::optional<Diagnosis>& d) {
  w.raw(static_cast<std::uint8_t>(d.has_value()));
  if (!d) return;
  w.raw(static_cast<std::int32_t>(d->family));
  w.text(d->channel);
  w.text(d->unit);
  w.raw(static_cast<std::int32_t>(d->source));
  for (double v : {d->band.low, d->band.high, d->spectral_kurtosis, d->family_share,
                   d->thresholds.min_spectral_kurtosis, d->thresholds.min_family_share})
    w.raw(v);
  encode_peaks(w, d->evidence);
  w.text(d->reason);
}

std::optional<Diagnosis> decode_diagnosis(Reader& r) {
  if (r.raw<std::uint8_t>() == 0) return std::nullopt;
  Diagnosis d;
  d.family = static_cast<FaultFamily>(r.raw<std::int32_t>());
  d.channel = r.text();
  d.unit = r.text();
  d.source = static_cast<EnvelopeBandSource>(r.raw<std::int32_t>());
  for (double* v : {&d.band.low, &d.band.high, &d.spectral_kurtosis, &d.family_share,
                    &d.thresholds.min_spectral_kurtosis, &d.thresholds.min_family_share})
    *v = r.raw<double>();
  d.evidence = decode_peaks(r);
  d.reason = r.text();
  return d;
}

void encode_microphone(Writer& w, const MicrophoneLevels& m) {
  for (double v : {m.microphone.radius, m.microphone.angle, m.position.x(), m.position.y(), m.p_rms,
                   m.p_rms_ring, m.p_rms_balls})
    w.raw(v);
  for (const auto* v : {&m.spl_total, &m.spl_ring, &m.spl_balls, &m.nearest_ball_surface})
    w.maybe(*v);
}

MicrophoneLevels decode_microphone(Reader& r) {
  MicrophoneLevels m;
  for (double* v : {&m.microphone.radius, &m.microphone.angle, &m.position.x(), &m.position.y(),
                    &m.p_rms, &m.p_rms_ring, &m.p_rms_balls})
    *v = r.raw<double>();
  for (auto* v : {&m.spl_total, &m.spl_ring, &m.spl_balls, &m.nearest_ball_surface}) *v = r.maybe();
  return m;
}

void encode_strings(Writer& w, const std::vector<std::string>& v) {
  w.size(v.size());
  for (const auto& s : v) w.text(s);
}

std::vector<std::string> decode_strings(Reader& r) {
  std::vector<std::string> v(r.size());
  for (auto& s : v) s = r.text();
  return v;
}

// `--save`'s tables of the row (sweep_tables.h), if it carries them.
void encode_tables(Writer& w, const SweepCaseTables* t) {
  w.raw(static_cast<std::uint8_t>(t != nullptr));
  if (!t) return;
  w.text(t->case_toml);
  w.text(t->summary_json);
  w.size(t->tables.size());
  for (const SweepTable& table : t->tables) {
    w.text(table.name);
    w.size(table.rows);
    encode_strings(w, table.columns);
    encode_strings(w, table.units);
    encode_strings(w, table.row_names);
    w.size(table.values.size());
    for (double v : table.values) w.raw(v);
  }
}

std::shared_ptr<const SweepCaseTables> decode_tables(Reader& r) {
  if (r.raw<std::uint8_t>() == 0) return nullptr;
  auto t = std::make_shared<SweepCaseTables>();
  t->case_toml = r.text();
  t->summary_json = r.text();
  t->tables.resize(r.size());
  for (SweepTable& table : t->tables) {
    table.name = r.text();
    table.rows = static_cast<std::size_t>(r.raw<std::uint64_t>());
    table.columns = decode_strings(r);
    table.units = decode_strings(r);
    table.row_names = decode_strings(r);
    table.values.resize(r.size());
    for (double& v : table.values) v = r.raw<double>();
  }
  return t;
}

}  // namespace

void encode_sweep_row(std::size_t index, const SweepRow& row, std::string& out) {
  Writer w(out);
  w.size(index);
  w.size(row.values.size());
  for (double v : row.values) w.raw(v);
  w.raw(static_cast<std::uint8_t>(row.ok));
  w.text(row.error);
  w.size(row.channels.size());
  for (const auto& c : row.channels) encode_channel(w, c);
  w.size(row.microphones.size());
  for (const auto& m : row.microphones) encode_microphone(w, m);
  w.size(row.envelopes.size());
  for (const auto& e : row.envelopes) encode_envelope(w, e);
  encode_diagnosis(w, row.diagnosis);
  encode_tables(w, row.tables.get());
}

SweepRow decode_sweep_row(std::string_view bytes, std::size_t& index) {
  Reader r(bytes);
  index = static_cast<std::size_t>(r.raw<std::uint64_t>());
  SweepRow row;
  row.values.resize(r.size());
  for (double& v : row.values) v = r.raw<double>();
  row.ok = r.raw<std::uint8_t>() != 0;
  row.error = r.text();
  const std::size_t channels = r.size();
  for (std::size_t i = 0; i < channels; ++i) row.channels.push_back(decode_channel(r));
  const std::size_t microphones = r.size();
  for (std::size_t i = 0; i < microphones; ++i) row.microphones.push_back(decode_microphone(r));
  const std::size_t envelopes = r.size();
  for (std::size_t i = 0; i < envelopes; ++i) row.envelopes.push_back(decode_envelope(r));
  row.diagnosis = decode_diagnosis(r);
  row.tables = decode_tables(r);
  r.finish();
  return row;
}

}  // namespace bearing
