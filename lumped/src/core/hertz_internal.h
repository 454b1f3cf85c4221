#pragma once
// Private helpers shared by the three Hertz methods (not part of the public interface).

#include <string_view>

namespace bearing::detail {

/// Throws InputError unless `f_rho` is a finite curvature difference in [0, 1); `method` is the
/// case-file name of the Hertz method, quoted in the message.
void require_curvature_difference(double f_rho, std::string_view method);

}  // namespace bearing::detail
