// The instances of ndof_linear.hpp's templates for double and mpfr (declared extern there).

#include <simpson/ndof_linear.hpp>

namespace simpson {

SIMPSON_NDOF_LINEAR_TEMPLATES(, double)
SIMPSON_NDOF_LINEAR_TEMPLATES(, ::simpson::mpfr)

}  // namespace simpson
