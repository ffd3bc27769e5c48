// The one instance per precision of newmark_map.hpp's templates (declared extern there).

#include <simpson/newmark_map.hpp>

namespace simpson {

#define SIMPSON_NEWMARK_MAP_INSTANTIATE(Real) SIMPSON_NEWMARK_MAP_TEMPLATES(, Real)
SIMPSON_FOR_EACH_PRECISION_TYPE(SIMPSON_NEWMARK_MAP_INSTANTIATE)

}  // namespace simpson
