// The vectorised RK4 stage arithmetic (bearing/solvers/rk4_loop.h): the inline loops compiled with
// the loop vectoriser, which rk4.cc is built without, for several instruction sets, the one the
// processor runs chosen when the program loads (target_clones). The loops are element by element
// and built without fused multiply-adds (-ffp-contract=off in CMake), so every instruction set
// gives the same bits.

#include "bearing/solvers/rk4_loop.h"
#include "bearing/target_clones.h"

namespace bearing::solvers_detail::rk4_wide {

BEARING_TARGET_CLONES void scale(double* a, const double* w, int n) {
  rk4_inline::scale(a, w, n);
}
BEARING_TARGET_CLONES void stage2(const Rk4Arrays& r, double hh) {
  rk4_inline::stage2(r, hh);
}
BEARING_TARGET_CLONES void stage3(const Rk4Arrays& r, double hh) {
  rk4_inline::stage3(r, hh);
}
BEARING_TARGET_CLONES void stage4(const Rk4Arrays& r, double h) {
  rk4_inline::stage4(r, h);
}
BEARING_TARGET_CLONES void finish(const Rk4Arrays& r, double h6) {
  rk4_inline::finish(r, h6);
}

}  // namespace bearing::solvers_detail::rk4_wide
