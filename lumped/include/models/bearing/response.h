#pragma once
// The time series of a run: typed channels (what each column is, its unit, whose it is) and the
// recorder that fills them from a model at each output instant, the same for every model kind.

#include <cstddef>
#include <string>
#include <vector>

#include "bearing/channel_group.h"
#include "bearing/models/model_outputs.h"

namespace bearing {

/// What one column of response.csv holds.
struct Channel {
  std::string name;  ///< "x", "vy", "Q3", ...
  std::string unit;  ///< SI unit
  ChannelGroup group = ChannelGroup::ring;
  int index = 0;       ///< ring: the DOF (0 = x), past the named DOFs a sensor row; ball: the ball
  int derivative = 0;  ///< ring: 0 displacement, 1 velocity, 2 acceleration
  BallField field = BallField::load;  ///< ball: which quantity
};

/// One per-ball quantity as a channel stem: "Q" + ball number.
struct BallChannelKind {
  BallField field;
  const char* stem;
  const char* unit;
};
/// In response.csv's column order.
inline constexpr BallChannelKind kBallChannels[] = {{BallField::load, "Q", "N"},
                                                    {BallField::approach, "d", "m"},
                                                    {BallField::radial, "r", "m"},
                                                    {BallField::radial_velocity, "vr", "m/s"},
                                                    {BallField::spin, "wb", "rad/s"},
                                                    {BallField::outer_load, "Qo", "N"},
                                                    {BallField::friction_inner, "Fi", "N"},
                                                    {BallField::friction_outer, "Fo", "N"},
                                                    {BallField::film_inner, "hi", "m"},
                                                    {BallField::film_outer, "ho", "m"}};

/// The per-ball channels a run writes (the [output] flags, and what the acoustics needs).
struct OutputRequest {
  bool ball_loads = false;     ///< Q1…QZ
  bool ball_approach = false;  ///< d1…dZ
  bool ball_motion = false;    ///< r1…rZ, vr1…vrZ
  bool ball_dynamics = false;  ///< wb, Qo, Fi, Fo (ball DOFs only)
  bool ball_film = false;      ///< hi, ho: central EHL film per contact (lubricated only)
  BallFields fields() const;
};

/// The output times: k / rate for k = 0 … ⌊duration·rate⌋, and the analysis window from
/// `transient` on.
struct OutputTimes {
  double duration = 1.2;   ///< [s]
  double transient = 0.2;  ///< [s]
  double rate = 20000.0;   ///< [Hz]
};

struct Response {
  std::vector<Channel> channels;            ///< ring DOFs, velocities, accelerations, then balls
  std::vector<double> time;                 ///< [s]
  std::vector<std::vector<double>> values;  ///< values[channel][sample], SI
  std::size_t first_steady = 0;             ///< first sample at or after the transient
  /// The random slip's cage angle error φ(t) at every sample [rad] (random_slip.h; empty
  /// without slip): where the balls were, for the acoustics' ball sources. Not a channel.
  std::vector<double> cage_slip;
  double rate = 0;  ///< samples per second [Hz]

  /// The index of the channel `name`; throws std::out_of_range for an unknown name.
  std::size_t index(const std::string& name) const;
  /// The samples of one channel; throws std::out_of_range for an unknown name.
  const std::vector<double>& channel(const std::string& name) const;
  /// The analysis window of one channel: the half-open interval [transient, duration), exactly
  /// (duration − transient)·rate samples, so spectral bins fall on multiples of
  /// 1/(duration − transient) (the last sample, at t = duration, is written but not analysed).
  std::vector<double> steady(const std::string& name) const;
};

/// The channels and times of a run of `model` (values zero-filled).
Response lay_out_response(const ModelOutputs& model, const OutputRequest& request,
                          const OutputTimes& times);

/// Fills a laid-out response one output instant at a time, in order: the ring's q, v, a (the
/// named DOFs', then the model's sensor rows'), then the requested ball fields from the model.
class ResponseRecorder {
 public:
  ResponseRecorder(const ModelOutputs& model, const OutputRequest& request, Response& response);
  void operator()(double t, const double* q, const double* v, const double* a);
  /// Samples recorded so far.
  std::size_t samples() const { return k_; }

 private:
  const ModelOutputs& model_;
  BallFields fields_;
  Response& out_;
  BallState balls_;
  std::size_t named_;               // the named DOFs; ring channels past them are sensor rows
  std::vector<SensorRow> sensors_;  // model_.sensor_rows()
  std::size_t k_ = 0;
};

}  // namespace bearing
