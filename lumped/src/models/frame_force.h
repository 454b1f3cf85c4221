#pragma once
// Private to the lumped models (not installed): the force-workspace boilerplate the three dynamic
// models (2-DOF, 3-DOF, ball DOFs) share.
//
// Why a CRTP base and not a virtual hook: force_with() is the hot path (one call per force
// evaluation); calling the model's force_in() statically lets the compiler inline it, so the
// evaluation costs one virtual call, as when each model spelled these lines out itself.

#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

#include "ball_set.h"
#include "bearing/solvers/mechanical_system.h"
#include "frame_workspace.h"

namespace bearing::detail {

/// Whether Model has force_in_inline(const Frame&, q, v, f) (force_at).
template <class M, class Frame, class = void>
struct HasInlineForce : std::false_type {};
template <class M, class Frame>
struct HasInlineForce<M, Frame,
                      std::void_t<decltype(std::declval<const M&>().force_in_inline(
                          std::declval<const Frame&>(), nullptr, nullptr, nullptr))>>
    : std::true_type {};

/// The workspace part of a model whose force at t depends on t only through the ball set's frame
/// (Frame: BallFrame or RaceFrame). Model derives from FrameForce<Model, Frame, Base> (Base:
/// BearingModel or an interface derived from it) and befriends it; it supplies
///   const BallSet& ball_set() const;
///   void force_in(const Frame& frame, const double* q, const double* v, double* f) const;
/// the generalised force f at the frame's time [N per DOF, SI of each DOF].
template <class Model, class Frame, class Base>
class FrameForce : public Base {
 public:
  /// A FrameWorkspace<Frame>: the frame at the last t asked for (frame_workspace.h).
  std::unique_ptr<MechanicalSystem::Workspace> make_workspace() const final {
    return std::make_unique<FrameWorkspace<Frame>>();
  }

  /// f at (t, q, v), the frame evaluated afresh at t.
  void force(double t, const double* q, const double* v, double* f) const final {
    FrameWorkspace<Frame> fresh;  // on the stack, evaluated at t
    force_with(&fresh, t, q, v, f);
  }

  /// f at (t, q, v), the frame kept in `workspace` (null: evaluated afresh).
  void force_with(MechanicalSystem::Workspace* workspace, double t, const double* q,
                  const double* v, double* f) const final {
    if (!workspace) return force(t, q, v, f);
    force_at(static_cast<FrameWorkspace<Frame>&>(*workspace), t, q, v, f);
  }

  /// force_with() for a caller that knows the model's type (static_rk4.h): no virtual call, so
  /// the force inlines into the caller's loop; `ahead`: the ball set's time_angles(t) computed
  /// ahead, or nullptr.
  /// A model with force_in_inline() (its per-ball loops inline: inline_contacts.h, the same bits
  /// as force_in) has it called here, with the frame's balls rotated inline too.
  [[gnu::always_inline]] void force_at(FrameWorkspace<Frame>& workspace, double t, const double* q,
                                       const double* v, double* f,
                                       const BallSet::TimeAngles* ahead = nullptr) const {
    const Model& model = static_cast<const Model&>(*this);
    if constexpr (HasInlineForce<Model, Frame>::value)
      model.force_in_inline(model.ball_set().template frame<Frame, true>(t, workspace, ahead), q, v,
                            f);
    else
      model.force_in(model.ball_set().template frame<Frame>(t, workspace, ahead), q, v, f);
  }

  /// The ball set's time_angles() of n times at once (BallSet::TimeAngles), for a caller
  /// computing them ahead.
  void time_angles(const double* t, int n, BallSet::TimeAngles* out,
                   std::vector<double>& scratch) const {
    static_cast<const Model&>(*this).ball_set().time_angles(t, n, out, scratch);
  }

  /// The ball set's random slip (random_slip.h).
  bool has_cage_slip() const final {
    return static_cast<const Model&>(*this).ball_set().slip() != nullptr;
  }
  double cage_slip_angle(double t) const final {
    const SlipPath* slip = static_cast<const Model&>(*this).ball_set().slip();
    return slip ? slip->angle(t) : 0.0;
  }

  using FrameType = Frame;
};

}  // namespace bearing::detail
