#pragma once
// The unit a measured record's values are stored in (`--unit`, a CSV header's "[g]", an HDF5
// attribute), and what it converts to: each unit belongs to one quantity, and one factor takes a
// stored value to SI. The name becomes the enum once, at the reader.

#include <optional>
#include <string>
#include <string_view>

#include "bearing/choice.h"

namespace bearing {

/// What a record measures; its samples are in the SI unit of that quantity.
enum class MeasuredQuantity {
  acceleration,  ///< m/s^2
  velocity,      ///< m/s
  displacement,  ///< m
};

inline constexpr Named<MeasuredQuantity> kMeasuredQuantities[] = {
    {MeasuredQuantity::acceleration, "acceleration"},
    {MeasuredQuantity::velocity, "velocity"},
    {MeasuredQuantity::displacement, "displacement"},
};

/// A stored value's unit.
enum class RecordUnit {
  g,         ///< standard gravity, 9.80665 m/s^2 (accelerometers' usual unit)
  m_per_s2,  ///< m/s^2
  m_per_s,   ///< m/s
  m,         ///< m
};

/// The names a user writes ("m/s2" and "m/s²" are also read as m/s^2, see parse_record_unit).
inline constexpr Named<RecordUnit> kRecordUnits[] = {
    {RecordUnit::g, "g"},
    {RecordUnit::m_per_s2, "m/s^2"},
    {RecordUnit::m_per_s, "m/s"},
    {RecordUnit::m, "m"},
};

/// The quantity a unit measures.
MeasuredQuantity quantity_of(RecordUnit unit);

/// The factor taking a value in `unit` to SI (g: 9.80665; the others 1).
double si_factor(RecordUnit unit);

/// The SI unit text of a quantity: "m/s^2", "m/s", "m".
std::string_view si_unit_of(MeasuredQuantity quantity);

/// The unit named `name` (one of kRecordUnits, or "m/s2", "m/s²"), or nothing.
std::optional<RecordUnit> find_record_unit(std::string_view name);

}  // namespace bearing
