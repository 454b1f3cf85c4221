#pragma once
// Private to the lumped models (not installed): a bearing model's force workspace
// (MechanicalSystem::force_with), the ball set's frame at the last t asked for.
//
// Why keep it: the frame (each ball's angle, excitation and contact constant, BallSet::evaluate)
// depends on t alone and costs about as much as the contact loop (2-DOF model: ~166 of ~430
// instructions per evaluation), and RK4 evaluates twice at t + h/2 and starts each step at the
// previous step's end time, so half its force calls can reuse it. Why here: the caller owns the
// workspace (one per integration), so the model stays immutable and force() const and
// thread-safe with no hidden per-thread state.

#include <limits>

#include "bearing/solvers/mechanical_system.h"

namespace bearing::detail {

/// The frame of type Frame (BallFrame or RaceFrame) at time t, filled by BallSet::frame().
template <class Frame>
struct FrameWorkspace final : MechanicalSystem::Workspace {
  double t = std::numeric_limits<double>::quiet_NaN();  ///< time of `frame` [s]; NaN: none yet
  Frame frame;
};

}  // namespace bearing::detail
