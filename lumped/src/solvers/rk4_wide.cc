// The vectorised RK4 stage arithmetic (bearing/solvers/rk4_loop.h): the inline loops compiled with
// the loop vectoriser, which rk4.cc is built without.

#include "bearing/solvers/rk4_loop.h"

namespace bearing::solvers_detail::rk4_wide {

void scale(double* a, const double* w, int n) {
  rk4_inline::scale(a, w, n);
}
void stage2(const Rk4Arrays& r, double hh) {
  rk4_inline::stage2(r, hh);
}
void stage3(const Rk4Arrays& r, double hh) {
  rk4_inline::stage3(r, hh);
}
void stage4(const Rk4Arrays& r, double h) {
  rk4_inline::stage4(r, h);
}
void finish(const Rk4Arrays& r, double h6) {
  rk4_inline::finish(r, h6);
}

}  // namespace bearing::solvers_detail::rk4_wide
