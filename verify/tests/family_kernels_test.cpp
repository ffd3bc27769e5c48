// The family's second kernel, stable ends and nonlinear step (verify/family): GiNaC with m, ω, h
// symbolic agrees with our kernel and catches a changed coefficient; Φ does not depend on where the
// internal nodes sit; a root of (tr Φ)² − 4 where Φ = ±I joins the stable set; the rules' nodes
// and weights; the implicit step's order on the pendulum.

#include <simpson/verify/galerkin_ginac.hpp>
#include <simpson/verify/galerkin_member.hpp>
#include <simpson/verify/galerkin_pendulum.hpp>
#include <simpson/verify/partitioned_pair.hpp>

#include <simpson/partitioned_runge_kutta.hpp>
#include <simpson/runge_kutta_tableaux.hpp>
#include <simpson/verify/exact_proof.hpp>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace simpson::verify {
namespace {

const galerkin_member phi3_member{2, {quadrature_family::newton_cotes, 3}};

TEST(FamilyKernels, GinacDerivesThePapersSchemeWithMOmegaHSymbolic) {
  const member_analysis ours = analyse_member(phi3_member);
  const ginac_member_check g = check_member_in_ginac(ours, 3);
  ASSERT_TRUE(g.derived) << g.failure;
  EXPECT_TRUE(g.det_one);
  EXPECT_TRUE(g.form_conserved);
  EXPECT_TRUE(g.same_as_exact_kernel);
  EXPECT_TRUE(g.scaling);
  ASSERT_TRUE(g.node_independent.has_value());
  EXPECT_TRUE(*g.node_independent);  // q_m anywhere in (0, 1): the same Φ₃
  EXPECT_NE(g.gamma.find("omega"), std::string::npos);  // symbolic, not at m = ω = 1
}

TEST(FamilyKernels, GinacCatchesOneChangedCoefficientOfOurKernel) {
  member_analysis ours = analyse_member(phi3_member);
  std::string& c = ours.map_coefficients[0][0].back();  // α's leading numerator coefficient
  c = c == "1" ? "2" : "1";
  const ginac_member_check g = check_member_in_ginac(ours, 0);
  EXPECT_FALSE(g.same_as_exact_kernel);
  EXPECT_FALSE(g.scaling);
  EXPECT_TRUE(g.det_one);  // GiNaC's own Φ is still symplectic
}

TEST(FamilyKernels, ANoMapMemberHasNoMapInGinacEither) {
  const member_analysis ours = analyse_member({3, {quadrature_family::newton_cotes, 2}});
  ASSERT_FALSE(ours.derived);
  member_analysis pretend = ours;
  pretend.derived = true;
  EXPECT_FALSE(check_member_in_ginac(pretend, 0).derived);
}

TEST(FamilyKernels, WhereGaussLegendreIsMinusIdentityTheStableSetDoesNotBreak) {
  // (s = 2, Gauss 2) is Gauss–Legendre 2: tr Φ = −2 at ωh = 2√3, where Φ = −I (power-bounded).
  const member_analysis a = analyse_member({2, {quadrature_family::gauss, 2}});
  ASSERT_TRUE(a.derived);
  ASSERT_EQ(a.stable_set.size(), 1u);
  EXPECT_EQ(piece_text(a.stable_set[0]), "(0, ∞)");
  // Φ₃ at 2√2 is a Jordan block: the band stays open there.
  const member_analysis phi3 = analyse_member(phi3_member);
  EXPECT_FALSE(phi3.stable_set[0].to_closed);
}

/// κ₁ of the rule's Vandermonde matrix, the condition of its weights' solve: ‖V‖₁ ‖V⁻¹‖₁.
long double vandermonde_condition(const numeric_rule& r) {
  const Eigen::Index n = static_cast<Eigen::Index>(r.nodes.size());
  Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic> V(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) V(i, j) = std::pow(r.nodes[static_cast<std::size_t>(j)], static_cast<long double>(i));
  }
  const auto norm1 = [](const auto& m) { return m.cwiseAbs().colwise().sum().maxCoeff(); };
  return norm1(V) * norm1(V.inverse());
}

TEST(FamilyKernels, NodesAndWeightsOfGaussAndLobatto) {
  // Nodes: Boost's Legendre zeros (Gauss) and bisection to the last bit on P′ (Lobatto), then one
  // rounding each in (1 ± z)/2: 4 ε. Weights: a Vandermonde solve, k ε κ₁(V) with k = 8 for the
  // LU's roundings and the moments' conversion.
  const long double eps = std::numeric_limits<long double>::epsilon();
  const numeric_rule gauss3 = nodes_and_weights({quadrature_family::gauss, 3});
  ASSERT_EQ(gauss3.nodes.size(), 3u);
  EXPECT_NEAR(gauss3.nodes[0], (1 - std::sqrt(0.6L)) / 2, 4 * eps);
  EXPECT_NEAR(gauss3.weights[1], 4.0L / 9, 8 * eps * vandermonde_condition(gauss3));
  const numeric_rule lobatto4 = nodes_and_weights({quadrature_family::lobatto, 4});
  ASSERT_EQ(lobatto4.nodes.size(), 4u);
  EXPECT_NEAR(lobatto4.nodes[1], (1 - 1 / std::sqrt(5.0L)) / 2, 4 * eps);
  EXPECT_NEAR(lobatto4.weights[0], 1.0L / 12, 8 * eps * vandermonde_condition(lobatto4));
}

TEST(FamilyKernels, TheImplicitStepKeepsItsLinearOrderOnThePendulum) {
  // The observed order is log2 of an error ratio: within 0.1 of the asymptotic order once h is small.
  const pendulum_order simpson = measure_pendulum_order(phi3_member, {16, 32, 64});
  ASSERT_TRUE(simpson.order.has_value()) << simpson.failure;
  EXPECT_NEAR(static_cast<double>(*simpson.order), 4, 0.1);
  const pendulum_order lobatto = measure_pendulum_order({3, {quadrature_family::lobatto, 4}}, {8, 16, 32});
  ASSERT_TRUE(lobatto.order.has_value()) << lobatto.failure;
  EXPECT_NEAR(static_cast<double>(*lobatto.order), 6, 0.1);
}

bool same(const one_step_matrix<symbolic>& a, const one_step_matrix<symbolic>& b) {
  return (a.alpha - b.alpha).is_zero() && (a.beta - b.beta).is_zero() && (a.gamma - b.gamma).is_zero() && (a.delta - b.delta).is_zero();
}

TEST(FamilyKernels, ThePairInTheNodalRingIsTheCoresLobattoIIIAIIIBAndImplicitMidpoint) {
  // The generic construction (no nodes, only the nodal polynomial and the moments) against the
  // core's tableaux with their own coefficients: Lobatto IIIA–IIIB 2 and 3 stages.
  const oscillator_parameters<symbolic> unit = unit_oscillator_in_theta();
  EXPECT_TRUE(same(family_detail::partitioned_pair_map({quadrature_family::lobatto, 2}),
                   partitioned_runge_kutta_map(unit, lobatto_iiia2_tableau<symbolic>(), lobatto_iiib2_tableau<symbolic>())));
  EXPECT_TRUE(same(family_detail::partitioned_pair_map({quadrature_family::lobatto, 3}),
                   partitioned_runge_kutta_map(unit, lobatto_iiia3_tableau<symbolic>(), lobatto_iiib3_tableau<symbolic>())));
  // Gauss 1: the pair is the implicit midpoint rule (Ā = A), the core's tableau.
  EXPECT_TRUE(same(family_detail::partitioned_pair_map({quadrature_family::gauss, 1}),
                   partitioned_runge_kutta_map(unit, implicit_midpoint_tableau<symbolic>(), implicit_midpoint_tableau<symbolic>())));
  // And the Galerkin member with Lobatto 4 (s = 3) is the 4-stage pair, whose tableaux hold √5.
  const member_analysis lobatto4 = analyse_member({3, {quadrature_family::lobatto, 4}});
  EXPECT_NE(std::find(lobatto4.equals.begin(), lobatto4.equals.end(), "Lobatto IIIA–IIIB, 4 stages"), lobatto4.equals.end());
}

}  // namespace
}  // namespace simpson::verify
