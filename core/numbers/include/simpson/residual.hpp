#pragma once
// A computed residual of an identity and the round-off bound it must respect, returned together
// by the checks that live beside each formula (as Boost.Math's cubic_roots does), so that the
// claims ledger and the property tests state each tolerance once.

namespace simpson {

/// With `zero_claimed` (an identity), `residual` is what the identity says is zero and `bound` is
/// k·eps·condition in the scalar it was computed in (zero for exact scalars, where the residual must
/// vanish). Without it, the claim is |residual| ≤ bound: `bound` is then a bound of the mathematics
/// (a series' tail), plus round-off in floating scalars only.
template <class Real>
struct residual_and_bound {
  Real residual;
  Real bound;
  bool zero_claimed = true;
};

}  // namespace simpson
