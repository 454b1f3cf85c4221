#include "mutations.h"

namespace bearing::verify {

namespace {

Perturbation with(void (*set)(Perturbation&)) {
  Perturbation p;
  set(p);
  return p;
}

}  // namespace

const std::vector<Mutation>& mutations() {
  static const std::vector<Mutation> table = {
      {"contact-constant-x1.03",
       "the lumped load-deflection constant K 3 % too stiff (both races and the series law)",
       with([](Perturbation& p) { p.contact_constant = 1.03; })},
      {"contact-exponent+0.05", "the lumped load-deflection exponent 1.55 instead of Hertz's 1.5",
       with([](Perturbation& p) { p.contact_exponent = 0.05; })},
      {"ellipse-minor-x1.01",
       "the contact ellipse's minor semi-axis b* 1 % too large (a slip in the ellipticity "
       "solution; K untouched)",
       with([](Perturbation& p) { p.ellipse_minor = 1.01; })},
      {"tvds-dropped", "the time-varying deflection stiffness (waviness curvature) term left out",
       with([](Perturbation& p) { p.drop_tvds = true; })},
      {"waviness-sign-swapped", "every waviness harmonic turned over (a sign error in the profile)",
       with([](Perturbation& p) { p.waviness_sign = true; })},
      {"cage-speed-1pct-slow",
       "the cage of the ball-DOF model 1 % slower than its kinematics (s_c + 0.01)",
       with([](Perturbation& p) { p.cage_slip = 0.01; })},
      {"pitch-diameter-x1.01", "the pitch diameter 1 % too large (kinematics and curvatures)",
       with([](Perturbation& p) { p.pitch_diameter = 1.01; })},
      {"mass-x1.05", "the inner-ring mass 5 % too large in the dynamic models",
       with([](Perturbation& p) { p.mass = 1.05; })},
      {"damping-x2", "the radial viscous damping doubled",
       with([](Perturbation& p) { p.damping = 2.0; })},
      {"sound-speed-x1.02", "the speed of sound 2 % too high in the lumped acoustics",
       with([](Perturbation& p) { p.sound_speed = 1.02; })},
      {"microphone-distance-x1.05", "every microphone placed 5 % too far from the bearing",
       with([](Perturbation& p) { p.microphone_distance = 1.05; })},
      {"fe-mesh-halved",
       "the FE meshes at half the resolution (cells across the contact / per radius)",
       with([](Perturbation& p) { p.fe_cells = 0.5; })},
      {"spall-width-x0.8", "every local defect 20 % narrower than the case says",
       with([](Perturbation& p) { p.defect_width = 0.8; })},
      {"analysis-speed-x1.05",
       "a measured record analysed at a shaft speed 5 % high (a speed reading or unit bug; "
       "beyond the ±3 % within which the record's shaft lines refine a given speed)",
       with([](Perturbation& p) { p.analysis_speed = 1.05; })},
      {"prewhitening-dropped", "a measured record's cepstral pre-whitening left out",
       with([](Perturbation& p) { p.drop_prewhitening = true; })},
      {"structure-young-x1.1",
       "a structure's Young's modulus 10 % high as bearing-fem modes reads it (a units slip in the "
       "structure file): every natural frequency 4.9 % high",
       with([](Perturbation& p) { p.structure_young = 1.1; })},
      {"modal-shapes-x1.05",
       "every mode shape read from modes.json 5 % large (a mass-normalisation slip): the seat's "
       "and the sensors' modal data, the effective masses 10 %",
       with([](Perturbation& p) { p.modal_shapes = 1.05; })},
      {"fe-degree-lowered",
       "the FE degree one below the one asked of bearing-fem modes (P1 tetrahedra for P2)",
       with([](Perturbation& p) { p.fe_degree = -1; })},
      {"false-alarm-x100",
       "the fault-line threshold computed for a false-alarm rate 100 times the stated one",
       with([](Perturbation& p) { p.false_alarm = 100; })},
  };
  return table;
}

const Mutation* find_mutation(const std::string& id) {
  for (const auto& m : mutations())
    if (m.id == id) return &m;
  return nullptr;
}

}  // namespace bearing::verify
