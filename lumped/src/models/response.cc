#include "bearing/response.h"

#include <cmath>
#include <stdexcept>

namespace bearing {

BallFields OutputRequest::fields() const {
  BallFields f = 0;
  if (ball_loads) f = f | BallField::load;
  if (ball_approach) f = f | BallField::approach;
  if (ball_motion) f = f | BallField::radial | BallField::radial_velocity;
  if (ball_dynamics)
    f = f | BallField::spin | BallField::outer_load | BallField::friction_inner |
        BallField::friction_outer;
  if (ball_film) f = f | BallField::film_inner | BallField::film_outer;
  return f;
}

std::size_t Response::index(const std::string& name) const {
  for (std::size_t i = 0; i < channels.size(); ++i)
    if (channels[i].name == name) return i;
  throw std::out_of_range("response has no channel \"" + name + "\"");
}

const std::vector<double>& Response::channel(const std::string& name) const {
  return values[index(name)];
}

std::vector<double> Response::steady(const std::string& name) const {
  const auto& v = channel(name);
  return std::vector<double>(v.begin() + static_cast<std::ptrdiff_t>(first_steady), v.end() - 1);
}

Response lay_out_response(const ModelOutputs& model, const OutputRequest& request,
                          const OutputTimes& times) {
  Response out;
  // The named DOFs, then the sensor rows (ring channels alike: each derivative's in one block).
  std::vector<std::string> dofs = model.dof_names();
  for (const SensorRow& row : model.sensor_rows()) dofs.push_back(row.name);
  static const char* const kPrefix[] = {"", "v", "a"};
  static const char* const kUnit[] = {"m", "m/s", "m/s^2"};
  for (int derivative = 0; derivative < 3; ++derivative)
    for (std::size_t i = 0; i < dofs.size(); ++i) {
      Channel ch;
      ch.name = kPrefix[derivative] + dofs[i];
      ch.unit = kUnit[derivative];
      ch.index = static_cast<int>(i);
      ch.derivative = derivative;
      out.channels.push_back(ch);
    }
  const BallFields fields = request.fields();
  for (const BallChannelKind& kind : kBallChannels) {
    if (!has(fields, kind.field)) continue;
    for (int j = 0; j < model.balls(); ++j) {
      Channel ch;
      ch.name = kind.stem + std::to_string(j + 1);
      ch.unit = kind.unit;
      ch.group = ChannelGroup::ball;
      ch.index = j;
      ch.field = kind.field;
      out.channels.push_back(ch);
    }
  }
  // The sample count from the duration, rounded to whole samples.
  const auto samples = static_cast<std::size_t>(std::floor(times.duration * times.rate + 1e-9)) + 1;
  out.time.resize(samples);
  for (std::size_t k = 0; k < samples; ++k) out.time[k] = static_cast<double>(k) / times.rate;
  out.rate = times.rate;
  out.first_steady = static_cast<std::size_t>(std::ceil(times.transient * times.rate - 1e-9));
  out.values.assign(out.channels.size(), std::vector<double>(samples));
  if (model.has_cage_slip()) out.cage_slip.resize(samples);
  return out;
}

ResponseRecorder::ResponseRecorder(const ModelOutputs& model, const OutputRequest& request,
                                   Response& response)
    : model_(model),
      fields_(request.fields()),
      out_(response),
      balls_(model.balls()),
      named_(model.dof_names().size()),
      sensors_(model.sensor_rows()) {}

void ResponseRecorder::operator()(double t, const double* q, const double* v, const double* a) {
  if (k_ >= out_.time.size()) throw std::logic_error("ResponseRecorder: more samples than times");
  if (fields_) model_.ball_state(t, q, v, fields_, balls_);
  if (!out_.cage_slip.empty()) out_.cage_slip[k_] = model_.cage_slip_angle(t);
  for (std::size_t i = 0; i < out_.channels.size(); ++i) {
    const Channel& ch = out_.channels[i];
    const auto dof = static_cast<std::size_t>(ch.index);
    double value = 0;
    if (ch.group == ChannelGroup::ring) {
      const double* x = ch.derivative == 0 ? q : ch.derivative == 1 ? v : a;
      if (dof < named_) {
        value = x[dof];
      } else {
        for (const auto& [i, weight] : sensors_[dof - named_].terms) value += weight * x[i];
      }
    } else {
      value = balls_[ch.field][dof];
    }
    out_.values[i][k_] = value;
  }
  ++k_;
}

}  // namespace bearing
