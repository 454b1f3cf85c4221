// The families of lines a case's excitations make (excitation_families.h).

#include "bearing/excitation_families.h"

#include <algorithm>

#include "bearing/models/model_registry.h"

namespace bearing {

namespace {

bool has_defect(const ModelInputs& in, DefectLocation where) {
  return std::any_of(in.defects.begin(), in.defects.end(),
                     [where](const LocalDefect& d) { return d.location == where; });
}

bool is_wavy(const Waviness& w) {
  return std::any_of(w.harmonics.begin(), w.harmonics.end(),
                     [](const WavinessHarmonic& h) { return h.amplitude != 0; });
}

}  // namespace

LineFamilies excitation_families(ModelKind kind, const ModelInputs& in) {
  const ModelDescriptor& model = model_descriptor(kind);
  const bool ball_defect = has_defect(in, DefectLocation::ball);
  const bool unequal_balls = std::any_of(in.ball_size_errors.begin(), in.ball_size_errors.end(),
                                         [](double e) { return e != 0; });
  const bool inner_features = is_wavy(in.inner_waviness) || has_defect(in, DefectLocation::inner);
  LineFamilies f;
  f.outer = true;
  f.outer_subharmonics = model.dynamic != nullptr;
  f.cage = unequal_balls || ball_defect || model.ball_dofs;
  f.inner = inner_features;
  f.shaft = in.unbalance != 0 || inner_features;
  f.spin = ball_defect;
  return f;
}

}  // namespace bearing
