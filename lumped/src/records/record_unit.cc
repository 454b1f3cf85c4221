#include "bearing/records/record_unit.h"

#include "bearing/constants.h"

namespace bearing {

MeasuredQuantity quantity_of(RecordUnit unit) {
  switch (unit) {
    case RecordUnit::g:
    case RecordUnit::m_per_s2:
      return MeasuredQuantity::acceleration;
    case RecordUnit::m_per_s:
      return MeasuredQuantity::velocity;
    case RecordUnit::m:
      return MeasuredQuantity::displacement;
  }
  return MeasuredQuantity::acceleration;
}

double si_factor(RecordUnit unit) {
  return unit == RecordUnit::g ? standard_gravity : 1.0;
}

std::string_view si_unit_of(MeasuredQuantity quantity) {
  switch (quantity) {
    case MeasuredQuantity::acceleration:
      return "m/s^2";
    case MeasuredQuantity::velocity:
      return "m/s";
    case MeasuredQuantity::displacement:
      return "m";
  }
  return "?";
}

std::optional<RecordUnit> find_record_unit(std::string_view name) {
  // The spellings of m/s^2 a header or a user writes besides the canonical one.
  if (name == "m/s2" || name == "m/s\xC2\xB2" || name == "m s^-2") return RecordUnit::m_per_s2;
  return find_named(kRecordUnits, name);
}

}  // namespace bearing
