#pragma once
// Leapfrog as VeriNum's VerifiedLeapfrog writes it (Kellison & Appel, NSV 2022; its C program
// lf_harm.c, integrated there in float32 with h = 1/32): unit mass, ω = 1, force F(q) = −q,
//   a = F(q);
//   q' = q + h p + (0.5 (h h)) a;
//   p' = p + (0.5 h) (a + F(q'));
// each operation rounded in the working format, in C's order of evaluation (left to right). The
// reference against which issue 29's proved round-off bounds are measured.

#include <simpson/one_step_map.hpp>

namespace simpson {

/// One step, operation for operation as in lf_harm.c (the constants 0.5 (h h) and 0.5 h computed
/// in the format, as the C program does).
template <class Real>
phase_point<Real> verinum_leapfrog_step(const Real& h, const phase_point<Real>& y) {
  const Real half(0.5);
  const Real a = -y.q;
  const Real q_next = y.q + h * y.p + (half * (h * h)) * a;
  return {y.p + (half * h) * (a + Real(-q_next)), q_next};
}

}  // namespace simpson
