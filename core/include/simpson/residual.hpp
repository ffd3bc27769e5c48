#pragma once
// A computed residual of an identity and the round-off bound it must respect, returned together
// by the checks that live beside each formula (as Boost.Math's cubic_roots does), so that the
// claims ledger and the property tests state each tolerance once.

namespace simpson {

/// `residual` is what the identity says is zero; `bound` is k·eps·condition in the scalar it was
/// computed in (zero for exact scalars, where the residual must vanish).
template <class Real>
struct residual_and_bound {
  Real residual;
  Real bound;
};

}  // namespace simpson
