#pragma once
// The schemes of the experiments by name: each advances by its own step algorithm (the stages a
// general implementation runs), and has its one-step matrix on the oscillator.

#include <simpson/newmark_map.hpp>
#include <simpson/runge_kutta_tableaux.hpp>
#include <simpson/simpson_elimination.hpp>
#include <simpson/simpson_map.hpp>
#include <simpson/stormer_verlet.hpp>

#include <array>
#include <stdexcept>
#include <string>

namespace simpson::verify::detail {

template <class Real>
class scheme_runner {
 public:
  /// Resolves the name once, so that step() does no string work on the timed path.
  scheme_runner(const std::string& name, const oscillator_parameters<Real>& par) : par_(par) {
    kind_ = name == "simpson"               ? kind::simpson
            : name == "simpson-elimination" ? kind::simpson_elimination
            : name == "stormer-verlet"      ? kind::stormer_verlet
            : name == "yoshida"             ? kind::yoshida
            : name == "newmark"             ? kind::newmark
                                            : kind::runge_kutta;
    if (name == "newmark") {
      for_q_ = for_p_ = implicit_midpoint_tableau<Real>();
    } else if (name == "gauss-legendre-2") {
      for_q_ = for_p_ = gauss_legendre2_tableau<Real>();
    } else if (name == "lobatto-iiia-iiib-3") {
      for_q_ = lobatto_iiia3_tableau<Real>();
      for_p_ = lobatto_iiib3_tableau<Real>();
    } else if (name == "rk4") {
      for_q_ = for_p_ = classic_rk4_tableau<Real>();
    } else if (name == "yoshida") {
      weights_ = yoshida_weights<Real>();
    } else if (name == "simpson") {
      phi3_ = simpson_map(par);
    } else if (name != "simpson-elimination" && name != "stormer-verlet") {
      throw std::invalid_argument("unknown scheme '" + name + "'");
    }
  }

  /// One step by the scheme's algorithm: Simpson by its explicit one-step map (Phi3), as the paper
  /// offers it for the oscillator; simpson-elimination by Section 6's elimination of the internal
  /// node at every step; Newmark as the implicit midpoint rule, Störmer–Verlet and Yoshida by their kicks and drifts,
  /// the Runge–Kutta peers by their stage equations.
  phase_point<Real> step(const phase_point<Real>& y) const {
    switch (kind_) {
      case kind::simpson: return phi3_ * y;
      case kind::simpson_elimination: return simpson_step_by_elimination(par_, y);
      case kind::stormer_verlet: return stormer_verlet_step(par_, y, par_.h());
      case kind::yoshida: return yoshida_step(par_, weights_, y);
      case kind::newmark:
      case kind::runge_kutta: break;
    }
    return partitioned_runge_kutta_step(par_, for_q_, for_p_, y);
  }

  /// The one-step matrix: (Phi3) and (matrice-symplectique-ordre-2) for the paper's schemes, the
  /// step applied to unit vectors for the peers.
  one_step_matrix<Real> matrix() const {
    switch (kind_) {
      case kind::simpson: return phi3_;
      case kind::simpson_elimination: return simpson_map(par_);
      case kind::stormer_verlet: return stormer_verlet_map(par_);
      case kind::yoshida: return yoshida_map(par_, weights_);
      case kind::newmark: return newmark_map(par_);
      case kind::runge_kutta: break;
    }
    return partitioned_runge_kutta_map(par_, for_q_, for_p_);
  }

 private:
  enum class kind { simpson, simpson_elimination, stormer_verlet, yoshida, newmark, runge_kutta };
  kind kind_;
  oscillator_parameters<Real> par_;
  butcher_tableau<Real> for_q_, for_p_;
  std::array<Real, 3> weights_{};
  one_step_matrix<Real> phi3_{};
};

/// Stages (force evaluations) per step, for the cost estimate.
inline double stages_of(const std::string& scheme) {
  if (scheme == "simpson") return 0.3;  // one 2 x 2 matrix product
  if (scheme == "simpson-elimination" || scheme == "lobatto-iiia-iiib-3") return 3;
  if (scheme == "yoshida") return 3;
  if (scheme == "rk4") return 4;
  if (scheme == "gauss-legendre-2") return 2;
  return 1;
}

}  // namespace simpson::verify::detail
