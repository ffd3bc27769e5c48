#pragma once
// The exception of a claim whose enclosure decides nothing within the run's precision budget (its
// verdict is then `undecided`). Free of MPFI, so that a claim deciding through an MPFI-free
// interface (table1_enclosed.hpp) can raise it without the interval headers.

#include <stdexcept>

namespace simpson::verify {

/// Thrown when an enclosure decides nothing within the run's precision budget: the claim's verdict
/// is then undecided, with this message as its evidence.
class enclosure_undecided : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace simpson::verify
