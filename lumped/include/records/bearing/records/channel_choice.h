#pragma once
// Which of a file's channels to read: the one RecordOptions::channel names, or the file's only
// one. Shared by every format so that "several channels" and "no such channel" read alike.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "bearing/records/record_options.h"

namespace bearing {

/// The index in `candidates` of the channel to read. `kind` names what a channel is in this
/// format for messages ("variable", "column", "channel", "dataset"). InputError naming the file
/// when: there is no candidate; there are several and options.channel is empty (listing them);
/// options.channel is not among them (listing them, and `also` when it is not empty: the names
/// that exist but are not channels, with why, e.g. "X130RPM (a 1×1 scalar)").
std::size_t choose_channel(const std::vector<std::string>& candidates, const RecordOptions& options,
                           const std::string& file, std::string_view kind,
                           const std::string& also = {});

/// "a, b, c".
std::string join_names(const std::vector<std::string>& names);

}  // namespace bearing
