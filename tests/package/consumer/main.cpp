// Links rotinterp::core from an installed package and checks exp/log agree.
#include <rotinterp/core/rotation.h>

#include <cstdio>

int main() {
  const rotinterp::RotVec v(0.1, -0.2, 0.3);
  const double err = (rotinterp::log(rotinterp::exp(v)).vec() - v.vec()).norm();
  std::printf("round-trip error %.3g\n", err);
  return err < 1e-12 ? 0 : 1;
}
