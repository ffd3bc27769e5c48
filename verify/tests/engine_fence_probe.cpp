// Never built by `make build`: the test engine.fence builds it and expects it not to compile. The
// claims engine and its shapes link the scalars (simpson::numbers), not the paper's formulas, so a
// core header is not on their include path; this file includes one as the engine would.
#include <simpson/verify/claim.hpp>
#include <simpson/shapes/proof_shapes.hpp>

#include <simpson/simpson_map.hpp>
