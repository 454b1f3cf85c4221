#pragma once
// The natural modes of the structure that carries the outer ring (a housing, an end shield, a
// pedestal), as `bearing-fem modes` computes them from a finite-element model and writes them to
// modes.json (fem/README.md, "Structure modes"), read back here for the case file's
// `[housing] modes = "DIR/modes.json"` (housing.h: the modal transfer path).
//
// The file's frame is the bearing's: z along the shaft, y up, x horizontal. Its shapes are
// mass-normalised, φ_kᵀ M φ_k = 1 with M in kg, so a shape value is a displacement per unit modal
// coordinate, in m/(kg^½ m) = kg^-½, and the modal coordinate η_k is in kg^½ m. What the lumped
// model takes of each mode k: its frequency f_k, the seat's rigid translation s_k (x, y, z) at
// the seat's centre (a least-squares fit of the seat's nodes; the tilts are in the file, but the
// 2-DOF and 3-DOF rings do not tilt) and each sensor's displacement ψ_k (x, y, z). Rigid-body
// modes are never in the file; a free-free structure says so (`boundary.free`), and cannot carry
// a bearing (it would drift away under the bearing's static load).
//
// The keys read (the file has more, for people and for bearing-fem's own checks):
//   {"format": "bearing-fem modes", "version": 1,
//    "boundary": {"free": false, ...},
//    "frequencies": [f_1, …, f_M],                         Hz, ascending
//    "seat": {"x": [M], "y": [M], "z": [M], ...},          kg^-½
//    "sensors": [{"name": "top", "point": [x, y, z],       m
//                 "x": [M], "y": [M], "z": [M]}, ...],     kg^-½
//    "units": {"frequency": "Hz", "shape": "kg^-1/2", ...}}

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace bearing {

/// The `format` string of the modes files this version reads, and their version.
inline constexpr std::string_view kModesFormat = "bearing-fem modes";
inline constexpr int kModesVersion = 1;
/// The most modes a modes file may hold (each is two state variables of a run).
inline constexpr int kMaxStructureModes = 500;

/// A point of the structure whose motion a run writes (an accelerometer's position).
struct StructureSensor {
  std::string name;                          ///< [A-Za-z0-9_]+: the channels' suffix (ay_<name>)
  std::array<double, 3> point{};             ///< where it is, in the file's frame [m]
  std::array<std::vector<double>, 3> shape;  ///< its x, y, z displacement per mode [kg^-½]
};

/// A validated modes file, SI units.
struct StructureModes {
  std::string path;                         ///< absolute path of the file read
  bool free = false;                        ///< no boundary held (free-free)
  std::vector<double> frequencies;          ///< f_k [Hz], ascending, > 0
  std::array<std::vector<double>, 3> seat;  ///< the seat's x, y, z translation per mode [kg^-½]
  std::vector<StructureSensor> sensors;

  int count() const { return static_cast<int>(frequencies.size()); }
  /// The sensor `name`, or nullptr.
  const StructureSensor* sensor(const std::string& name) const;
};

/// Parses a modes file's text; `path` is recorded, `shown` starts every message (e.g.
/// `housing.modes = "modes.json"`). Throws InputError naming the key, the value and what is
/// allowed.
StructureModes parse_structure_modes(std::string_view json_text, const std::string& path,
                                     const std::string& shown);

/// Reads and parses the file at `path` (InputError if it cannot be read).
StructureModes read_structure_modes(const std::string& path, const std::string& shown);

}  // namespace bearing
