#pragma once
// Catalogue of the bearings the seed papers study, each with its source.

#include <string>
#include <vector>

#include "bearing/bearing.h"

namespace bearing {

/// The preset with this designation ("608", "6304", "6308", "6205", "6203", "209"); throws InputError
/// naming the key `bearing.preset` and listing the known designations.
Bearing preset(const std::string& designation);

/// Designations of all presets, in catalogue order.
std::vector<std::string> preset_names();

/// One line saying where a preset's numbers come from.
std::string preset_source(const std::string& designation);

}  // namespace bearing
