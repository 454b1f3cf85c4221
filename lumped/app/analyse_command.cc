// `bearing-sim analyse`: read a measured record, analyse it, write run's files, print the summary.

#include "analyse_command.h"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>

#include "bearing/case_file.h"
#include "bearing/cli_options.h"
#include "bearing/errors.h"
#include "bearing/record_analysis.h"
#include "bearing/record_output.h"
#include "bearing/records/record_formats.h"
#include "bearing/units.h"
#ifdef BEARING_WITH_RECORDS_FULL
#include "bearing/records/full_record_formats.h"
#endif

namespace bearing_app {

namespace {

using bearing::InputError;

std::vector<bearing::RecordFormat> record_formats() {
#ifdef BEARING_WITH_RECORDS_FULL
  return bearing::with_formats(bearing::base_record_formats(), bearing::full_record_formats());
#else
  return bearing::base_record_formats();
#endif
}

// Whether bearing-sim-full reads this extension where this program does not (full_program.h):
// BEARING_FULL_READS lists the extensions of bearing_records_full's readers in this build (those
// that load libsndfile, matio or HDF5).
bool read_by_full_program(const bearing::RecordFormat& f) {
#ifdef BEARING_FULL_READS
  const std::string list = std::string(" ") + BEARING_FULL_READS + " ";
  return !f.read && list.find(" " + std::string(f.extension) + " ") != std::string::npos;
#else
  (void)f;
  return false;
#endif
}

std::string format_list() {
  std::string out;
  for (const auto& f : record_formats())
    out += "\n  " + std::string(f.extension) + "  " + std::string(f.description) +
           (f.read || read_by_full_program(f) ? "" : " (" + std::string(f.unavailable) + ")");
  return out;
}

// The bearing must be named: the built-in default case's 6308 is not a measured bearing.
bearing::Case load_case(const AnalyseOptions& o) {
  std::vector<bearing::Override> overrides;
  bool names_bearing = false;
  for (const auto& s : o.sets) {
    overrides.push_back(bearing::parse_override(s));
    names_bearing = names_bearing || overrides.back().key.rfind("bearing.", 0) == 0;
  }
  if (o.case_path.empty() && !names_bearing)
    throw InputError(
        "analyse: name the record's bearing: a CASE file (bearing.preset = \"6205\" suffices) or "
        "--set bearing.preset=6205");
  return o.case_path.empty() ? bearing::default_case(overrides)
                             : bearing::read_case_file(o.case_path, overrides);
}

// A plain number in SI (a rate of 12000 is 12000 Hz) or a value with its unit ("12 kHz").
double frequency_option(const std::string& text, const std::string& option) {
  std::size_t used = 0;
  try {
    const double v = std::stod(text, &used);
    if (used == text.size()) return v;
  } catch (const std::exception&) {
  }
  return bearing::parse_quantity(text, bearing::Dimension::frequency, option);
}

// A speed always with its unit: a bare 1797 would be read as rad/s, not the rpm meant.
double speed_option(const std::string& text, const std::string& option) {
  return bearing::parse_quantity(text, bearing::Dimension::angular_speed, option);
}

struct SpeedChoice {
  bearing::SpeedSetting setting;
  std::string origin;  ///< RecordOrigin::speed_origin
};

// The speed --speed names, else the record's stored one, else the case's operation.speed: a speed
// stored in the record belongs to it, a case file may describe the bearing of many records.
SpeedChoice speed_of(const AnalyseOptions& o, const bearing::MeasuredRecord& r,
                     const bearing::Case& c) {
  using bearing::SpeedSource;
  const std::string where_case = "operation.speed of " + c.source;
  const bool estimate = o.speed == "estimate" || o.speed.rfind("estimate:", 0) == 0;
  if (!o.speed.empty() && !estimate)
    return {{SpeedSource::option, speed_option(o.speed, "--speed")}, "--speed " + o.speed};
  if (estimate && o.speed.size() > 9)
    return {{SpeedSource::estimate, speed_option(o.speed.substr(9), "--speed estimate:NOMINAL")},
            "estimated near --speed " + o.speed.substr(9)};
  std::optional<SpeedChoice> known;
  if (r.shaft_speed)
    known = SpeedChoice{{SpeedSource::record, *r.shaft_speed}, r.shaft_speed_origin};
  else if (c.operation.speed > 0)
    known = SpeedChoice{{SpeedSource::case_file, c.operation.speed}, where_case};
  if (!known)
    throw InputError(r.file + ": no shaft speed: the record stores none and " + where_case +
                     " is 0; give --speed 1797rpm, --speed estimate:1800rpm or operation.speed");
  if (!estimate) return *known;
  return {{SpeedSource::estimate, known->setting.speed}, "estimated near " + known->origin};
}

// "--rate", "--rate (agreeing with the WAV header)" or "the WAV header".
std::string where(bearing::RecordSource source, const std::string& option,
                  const std::string& in_file) {
  if (source == bearing::RecordSource::file) return in_file;
  return in_file.empty() ? option : option + " (agreeing with " + in_file + ")";
}

// --band: "auto", "none" or "LOW:HIGH" with units ("2kHz:4kHz").
bearing::EnvelopeBandSetting band_of(const std::string& text) {
  if (text == "auto") return {bearing::EnvelopeBandSource::automatic, {}};
  if (text == "none") return {bearing::EnvelopeBandSource::none, {}};
  const auto colon = text.find(':');
  if (colon == std::string::npos)
    throw InputError("--band " + text + ": allowed auto, none or LOW:HIGH (e.g. 2kHz:4kHz)");
  return {bearing::EnvelopeBandSource::given,
          {frequency_option(text.substr(0, colon), "--band LOW"),
           frequency_option(text.substr(colon + 1), "--band HIGH")}};
}

}  // namespace

CLI::App* add_analyse_command(CLI::App& app, AnalyseOptions& o) {
  auto* cmd = app.add_subcommand(
      "analyse",
      "Analyse a measured vibration record as `run` analyses a simulated one: statistics, "
      "spectrum with named peaks, envelope (kurtogram band) of the cepstrally pre-whitened "
      "record, its squared envelope spectrum, each fault family's lines (slip window, harmonics, "
      "sidebands) rated over the floor [dB] against a threshold from a false-alarm rate, and the "
      "diagnosis (outer | inner | ball | none) with its evidence. Writes DIR/spectrum.csv, "
      "DIR/envelope.csv (env_<ch>, ses_<ch>) and DIR/summary.json (the record's file, channel, "
      "rate, unit, speed and its source), as `run` does, so bearing-plot DIR draws them; prints "
      "the summary. The rate and unit are never guessed: give --rate and --unit where the file "
      "does not state them.");
  cmd->add_option("RECORD", o.record, "The record's file; formats:" + format_list())->required();
  cmd->add_option("CASE", o.case_path,
                  "TOML case file naming the bearing (bearing.preset = \"6205\" suffices) and "
                  "optionally operation.speed; or name it with --set bearing.preset=...");
  cmd->add_option("--set", o.sets, "Override one case-file value (repeat for more)")
      ->type_name("TABLE.KEY=VALUE")
      ->allow_extra_args(false);
  cmd->add_option("--out", o.out_dir, "Folder for the result files (created if missing)")
      ->required();
  cmd->add_option("--channel", o.channel,
                  "The variable (.mat), column (.csv, .npy), channel (.wav) or 2-D dataset column "
                  "(.h5) to read; default: the file's only one (else an error lists them)");
  cmd->add_option("--rate", o.rate,
                  "Sampling rate, e.g. 12000 or \"48 kHz\", where the file does not state it "
                  "(.mat, .npy, CSV without time column); checked against it where it does");
  cmd->add_option("--unit", o.unit,
                  "Unit of the stored values (times --scale): g | m/s^2 | m/s | m, where the file "
                  "does not state it");
  cmd->add_option("--scale", o.scale,
                  "Stored value x scale = value in --unit (a sensitivity, a full scale); default 1")
      ->capture_default_str();
  cmd->add_option("--dataset", o.dataset, ".h5: the dataset's path (default: the only one)");
  cmd->add_option("--speed", o.speed,
                  "Inner-ring (shaft) speed: \"1797rpm\", \"estimate\" (from the record's own "
                  "shaft harmonics within +-10 % of the stored or case speed) or "
                  "\"estimate:1800rpm\"; default: the speed the record stores (a CWRU file's "
                  "XNNNRPM), else the case's operation.speed");
  cmd->add_option("--band", o.band,
                  "Envelope band: auto (the kurtogram's, default), none, or LOW:HIGH "
                  "(e.g. 2kHz:4kHz)")
      ->capture_default_str();
  cmd->add_flag("--prewhiten,!--no-prewhiten", o.prewhiten,
                "Cepstral pre-whitening before the kurtogram and envelope (default on: it "
                "removes the shaft, gear and electrical lines a measured record carries)");
  cmd->add_option("--rule", o.rule,
                  "Diagnosis rule: coherence (each family in its band of the pre-whitened "
                  "record's cyclic-coherence map, with decoys and each family's sidebands; "
                  "default) | line_to_floor (the kurtogram band's squared envelope spectrum) | "
                  "envelope_peaks (run's rule)")
      ->capture_default_str();
  cmd->add_option("--false-alarm", o.false_alarm,
                  "Probability that a family's lines in a fault-free record pass the threshold")
      ->check(bearing::cli::range(1e-12, 0.5))
      ->capture_default_str();
  cmd->add_option("--slip", o.slip,
                  "Half-width of the window a fault line is searched in, relative to its "
                  "nominal frequency (default 0.02: real bearings slip 1-2 %)")
      ->check(bearing::cli::range(0, 0.1))
      ->capture_default_str();
  cmd->add_option("--speed-refinement", o.speed_refinement,
                  "A given speed is refined from the record's shaft harmonics within this "
                  "fraction where they stand out (0: used as given)")
      ->check(bearing::cli::range(0.0, 0.099))
      ->capture_default_str();
  cmd->add_option("--harmonics", o.harmonics,
                  "Fault-rate harmonics searched by line_to_floor (default 3; coherence: 3)")
      ->check(bearing::cli::range(1, 10))
      ->capture_default_str();
  cmd->add_flag("--json", o.json, "Print summary.json instead of the readable summary");
  cmd->add_flag("--quiet", o.quiet, "No timing line on stderr");
  return cmd;
}

int analyse_command(const AnalyseOptions& o, const CommandLine& cl) {
  const std::vector<bearing::RecordFormat> formats = record_formats();
  std::string extension = std::filesystem::path(o.record).extension().string();
  for (char& ch : extension) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  for (const auto& f : formats)
    if (f.extension == extension && read_by_full_program(f))
      hand_over(cl, "reading a " + extension + " record");
  const bearing::Case c = load_case(o);
  bearing::RecordOptions ro;
  ro.channel = o.channel;
  if (!o.rate.empty()) ro.rate = frequency_option(o.rate, "--rate");
  ro.unit = o.unit;
  ro.scale = o.scale;
  ro.dataset = o.dataset;
  const bearing::MeasuredRecord r = bearing::read_record(o.record, ro, formats);
  const SpeedChoice speed = speed_of(o, r, c);

  bearing::RecordAnalysisSettings s;
  s.window = c.output.window;
  s.peaks = c.output.peaks;
  s.envelope = band_of(o.band);
  s.prewhiten = o.prewhiten;
  s.rule = bearing::parse_named(bearing::kDiagnosisRules, o.rule, "--rule", "diagnosis rule");
  s.lines.false_alarm = o.false_alarm;
  s.lines.slip = o.slip;
  s.lines.harmonics = o.harmonics;
  s.speed_refinement = o.speed_refinement;
  s.coherence.slip = o.slip;
  if (s.rule == bearing::DiagnosisRule::coherence) s.coherence.false_alarm = o.false_alarm;
  bearing::RecordOrigin origin;
  origin.file = o.record;
  origin.case_source = o.case_path.empty() ? "" : c.source;
  origin.speed_origin = speed.origin;
  origin.stored_unit = bearing::name_of(bearing::kRecordUnits, r.unit);
  origin.scale = r.scale;
  origin.rate_origin = where(r.rate_source, "--rate", r.rate_origin);
  origin.unit_origin = where(r.unit_source, "--unit", r.unit_origin);
  bearing::RecordAnalysis a;
  try {
    a = bearing::analyse_record(r.samples, r.rate, r.channel,
                                std::string(bearing::si_unit_of(r.quantity)), c.bearing,
                                speed.setting, s);
  } catch (const InputError& e) {  // name the record, as the reader's errors do
    throw InputError(o.record + ", channel " + r.channel + ": " + e.what());
  }
  bearing::write_record_analysis(o.out_dir, a, origin, c.output.format);
  if (o.json)
    std::cout << bearing::record_summary_json(a, origin).dump(2) << "\n";
  else
    std::cout << bearing::record_summary_text(a, origin);
  if (!o.quiet) std::fprintf(stderr, "analyse: wrote %s/\n", o.out_dir.c_str());
  return 0;
}

}  // namespace bearing_app
