// The one instance per precision of simpson_map.hpp's templates (declared extern there).

#include <simpson/simpson_map.hpp>

namespace simpson {

#define SIMPSON_MAP_INSTANTIATE(Real) SIMPSON_MAP_TEMPLATES(, Real)
SIMPSON_FOR_EACH_PRECISION_TYPE(SIMPSON_MAP_INSTANTIATE)

}  // namespace simpson
