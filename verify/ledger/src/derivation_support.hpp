#pragma once
// The engine's GiNaC helpers (printed_check_support.hpp) with the paper's own derivation: the
// oscillator's parameters for the core's templates, the derived Gear values, and the truncation
// series of the derived scheme (section 5). The book's checks use these; the proof shapes do not.

#include "symbolic_derivation.hpp"

#include <simpson/prove/printed_check_support.hpp>

#include <simpson/one_step_map.hpp>
#include <simpson/oscillator_parameters.hpp>

#include <ginac/ginac.h>

namespace simpson::verify::detail {

/// The oscillator's parameters (m, ω, h) of the derivation, for the core's templates.
oscillator_parameters<GiNaC::ex> parameters(const symbolic_derivation& d);

/// A one-step matrix of the core as a GiNaC matrix.
inline GiNaC::matrix as_matrix(const one_step_matrix<GiNaC::ex>& phi) { return GiNaC::matrix{{phi.alpha, phi.beta}, {phi.gamma, phi.delta}}; }

/// A printed formula with g_l, g_m, g_r replaced by the derived Gear values.
GiNaC::ex with_gear(const GiNaC::ex& e, const symbolic_derivation& d);

/// T_h(q_j) of the derived scheme, normalised as `normalised_like` (a scheme whose q_{j+1}
/// coefficient fixes the scale, the core's (schema-ordre-3)), on the exact solution, to O(h^order).
GiNaC::ex truncation_series(const symbolic_derivation& d, const GiNaC::ex& normalised_like, int order);

/// The derived scheme normalised as `normalised_like` (the factor truncation_series uses).
GiNaC::ex normalised_scheme(const symbolic_derivation& d, const GiNaC::ex& normalised_like);

}  // namespace simpson::verify::detail
