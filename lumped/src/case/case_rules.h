#pragma once
// Private to the case schema: the tables whose keys need more than one value each — the bearing
// preset, waviness entries (or a CSV table), ball-size errors (given or drawn), local defects, the
// calibration file, the envelope band (a word or two frequencies), and the rules that tie the
// [solver] and [acoustics] keys together.

#include <ostream>
#include <string>

#include "case_schema.h"

namespace bearing::case_schema {

/// bearing.preset: the catalogue bearing that the other [bearing] keys override.
void read_preset(TableReader& r, Case& c, const ReadContext& context);

/// [[waviness.<race>]] entries: order, amplitude, phase, or table = "file.csv".
void read_waviness(TableReader& parent, const std::string& race, Case& c,
                   const ReadContext& context);
void write_waviness(std::ostream& o, const Case& c);

/// [ball_errors]: values per ball, or a band drawn with a seed.
void read_ball_errors(TableReader& r, Case& c, const ReadContext& context);
void write_ball_errors(std::ostream& o, const Case& c);

/// One [[defects]] entry: location, position, ball, width, depth, profile; and their rules once
/// all are read (check_defects, a model kind that integrates in time).
void read_defect(TableReader& r, Case& c, const ReadContext& context);
void check_defect_entries(Case& c);
void write_defects(std::ostream& o, const Case& c);

/// model.calibration: read and checked against the bearing now, so a calibration for another
/// bearing never reaches a model.
void read_calibration_file(TableReader& r, Case& c, const ReadContext& context);

/// output.envelope_band: "none" (the default; not written), "auto", or [low, high] [Hz], within
/// 0 <= low < high <= solver.output_rate / 2.
void read_envelope_band(TableReader& r, Case& c, const ReadContext& context);
void check_envelope_band(const Case& c);
void write_envelope_band(std::ostream& o, const Case& c);

/// [housing] (housing_rules.cc): modes = "modes.json" (bearing-fem modes), read now relative to
/// the case file; damping_ratio, one number or one per mode; sensors, the modes file's sensors a
/// run writes; and the table's rules (the resonator or the modes, check_housing).
void read_housing_modes(TableReader& r, Case& c, const ReadContext& context);
void write_housing_modes(std::ostream& o, const Case& c);
void read_housing_damping(TableReader& r, Case& c, const ReadContext& context);
void write_housing_damping(std::ostream& o, const Case& c);
void read_housing_sensors(TableReader& r, Case& c, const ReadContext& context);
void write_housing_sensors(std::ostream& o, const Case& c);
void check_housing_table(Case& c);

/// solver.transient against solver.duration, and the number of output samples.
void check_solver_times(Case& c);

/// The microphones against the sources, and that something radiates.
void check_acoustics(Case& c);
void write_microphones(std::ostream& o, const Case& c);

}  // namespace bearing::case_schema
