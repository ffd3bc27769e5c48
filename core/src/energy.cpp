// The one instance per precision of energy.hpp's templates (declared extern there).

#include <simpson/energy.hpp>

namespace simpson {

#define SIMPSON_ENERGY_INSTANTIATE(Real) SIMPSON_ENERGY_TEMPLATES(, Real)
SIMPSON_FOR_EACH_PRECISION_TYPE(SIMPSON_ENERGY_INSTANTIATE)

}  // namespace simpson
