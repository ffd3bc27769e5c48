#pragma once
// The schemes the harness compares: the paper's two (Newmark, Section 2; Simpson, Section 6), the
// paper's own elimination route, and the peers. One list (scheme_list) gives each its name, order
// and stages per step; the names, orders, cost estimates and dispatch of the rest of the project
// come from it. A `stepper` advances by the scheme's own algorithm (what a general implementation
// runs) and gives its one-step matrix on the oscillator.

#include <simpson/explicit_runge_kutta.hpp>
#include <simpson/newmark_map.hpp>
#include <simpson/runge_kutta_tableaux.hpp>
#include <simpson/simpson_elimination.hpp>
#include <simpson/simpson_map.hpp>
#include <simpson/stormer_verlet.hpp>

#include <array>
#include <stdexcept>
#include <string>
#include <string_view>

namespace simpson {

enum class scheme_id {
  newmark,
  simpson,
  simpson_elimination,
  stormer_verlet,
  yoshida,
  gauss_legendre_2,
  lobatto_iiia_iiib_3,
  rk4
};

struct scheme_traits {
  scheme_id id;
  std::string_view name;
  int order;     // global order of accuracy
  double stages; // force evaluations per step (0.3 for Simpson's single 2 × 2 product), for cost estimates
  bool symplectic;
};

/// Every scheme, in the order reports list them.
inline constexpr std::array<scheme_traits, 8> scheme_list{{
    {scheme_id::newmark, "newmark", 2, 1, true},
    {scheme_id::simpson, "simpson", 4, 0.3, true},
    {scheme_id::simpson_elimination, "simpson-elimination", 4, 3, true},
    {scheme_id::stormer_verlet, "stormer-verlet", 2, 1, true},
    {scheme_id::yoshida, "yoshida", 4, 3, true},
    {scheme_id::gauss_legendre_2, "gauss-legendre-2", 4, 2, true},
    {scheme_id::lobatto_iiia_iiib_3, "lobatto-iiia-iiib-3", 4, 3, true},
    {scheme_id::rk4, "rk4", 4, 4, false},
}};

/// The scheme named `name`; throws std::invalid_argument naming it and the known names otherwise.
inline const scheme_traits& find_scheme(std::string_view name) {
  for (const scheme_traits& s : scheme_list) {
    if (s.name == name) return s;
  }
  std::string known;
  for (const scheme_traits& s : scheme_list) known += (known.empty() ? "" : ", ") + std::string(s.name);
  throw std::invalid_argument("unknown scheme '" + std::string(name) + "' (expected " + known + ")");
}

inline const scheme_traits& traits_of(scheme_id id) {
  for (const scheme_traits& s : scheme_list) {
    if (s.id == id) return s;
  }
  throw std::logic_error("traits_of: scheme missing from scheme_list");
}

/// A scheme set up for one (m, ω, h): step() by the scheme's algorithm, matrix() its one-step matrix.
template <class Real>
class stepper {
 public:
  stepper(scheme_id id, const oscillator_parameters<Real>& par) : id_(id), par_(par) {
    switch (id) {
      case scheme_id::newmark: for_q_ = for_p_ = implicit_midpoint_tableau<Real>(); break;
      case scheme_id::gauss_legendre_2: for_q_ = for_p_ = gauss_legendre2_tableau<Real>(); break;
      case scheme_id::lobatto_iiia_iiib_3:
        for_q_ = lobatto_iiia3_tableau<Real>();
        for_p_ = lobatto_iiib3_tableau<Real>();
        break;
      case scheme_id::rk4:
        for_q_ = for_p_ = classic_rk4_tableau<Real>();
        explicit_ = explicit_tableau<Real>(for_q_);
        break;
      case scheme_id::yoshida: weights_ = yoshida_weights<Real>(); break;
      case scheme_id::simpson: phi3_ = simpson_map(par); break;
      case scheme_id::simpson_elimination:
      case scheme_id::stormer_verlet: break;
    }
    // The implicit peers' stage matrix is constant for the linear force: factored once here.
    if (id == scheme_id::newmark || id == scheme_id::gauss_legendre_2 || id == scheme_id::lobatto_iiia_iiib_3) {
      stages_ = factor_linear_stages(par_, for_q_, for_p_);
    }
  }

  const scheme_traits& traits() const { return traits_of(id_); }

  /// One step by the scheme's algorithm, as its users write it for this linear force: Simpson by its
  /// explicit one-step map (Phi3), as the paper offers it for the oscillator; simpson-elimination by
  /// Section 6's elimination of the internal node at every step; Newmark as the implicit midpoint
  /// rule, Gauss–Legendre and Lobatto IIIA–IIIB by their stage equations, the constant stage matrix
  /// factored once (factor_linear_stages); Störmer–Verlet and Yoshida by their kicks and drifts; RK4
  /// by its four explicit stages.
  phase_point<Real> step(const phase_point<Real>& y) const {
    switch (id_) {
      case scheme_id::simpson: return phi3_ * y;
      case scheme_id::simpson_elimination: return simpson_step_by_elimination(par_, y);
      case scheme_id::stormer_verlet: return stormer_verlet_step(par_, y, par_.h());
      case scheme_id::yoshida: return yoshida_step(par_, weights_, y);
      case scheme_id::rk4: return explicit_runge_kutta_step(par_, explicit_, y);
      case scheme_id::newmark:
      case scheme_id::gauss_legendre_2:
      case scheme_id::lobatto_iiia_iiib_3: break;
    }
    return factored_prk_step(par_, for_q_, for_p_, stages_, y);
  }

  /// The one-step matrix: (Phi3) and (matrice-symplectique-ordre-2) for the paper's schemes, the
  /// step applied to unit vectors for the peers.
  one_step_matrix<Real> matrix() const {
    switch (id_) {
      case scheme_id::simpson: return phi3_;
      case scheme_id::simpson_elimination: return simpson_map(par_);
      case scheme_id::stormer_verlet: return stormer_verlet_map(par_);
      case scheme_id::yoshida: return yoshida_map(par_, weights_);
      case scheme_id::newmark: return newmark_map(par_);
      case scheme_id::gauss_legendre_2:
      case scheme_id::lobatto_iiia_iiib_3:
      case scheme_id::rk4: break;
    }
    return partitioned_runge_kutta_map(par_, for_q_, for_p_);
  }

 private:
  scheme_id id_;
  oscillator_parameters<Real> par_;
  butcher_tableau<Real> for_q_, for_p_;
  std::array<Real, 3> weights_{};
  one_step_matrix<Real> phi3_{};
  factored_linear_stages<Real> stages_{};
  explicit_tableau<Real> explicit_{};
};

}  // namespace simpson
