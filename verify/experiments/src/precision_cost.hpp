#pragma once
// The cost of a step in each precision relative to double (experiment_cost.hpp's units), shared by
// the sections' estimates.

#include <simpson/precision.hpp>

namespace simpson::verify {

/// Cost of one arithmetic-heavy step in a precision relative to double, measured on the 2-core
/// machine (Φ₃ iteration with the energy monitor): software float128 and multiprecision are slower.
inline double precision_factor(const precision& p) {
  switch (p.kind()) {
    case precision_kind::float64: return 1;
    case precision_kind::extended: return 2;
    case precision_kind::float128: return 20;
    case precision_kind::bin50: return 60;
    case precision_kind::bin100: return 120;
    case precision_kind::mpfr: return 30 + static_cast<double>(p.digits10()) / 5;
    case precision_kind::rational: return 1e6;
  }
  return 1;
}

}  // namespace simpson::verify
