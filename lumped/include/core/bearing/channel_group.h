#pragma once
// Whose a channel is: a run's response names its channels with it (models' response.h) and the
// summaries of channels carry it, also in the analysis above signal, which does not see models.

namespace bearing {

/// Whose a channel is: the inner ring's, one ball's, or a microphone's.
enum class ChannelGroup { ring, ball, acoustic };

}  // namespace bearing
