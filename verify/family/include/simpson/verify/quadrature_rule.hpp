#pragma once
// Quadrature rules on [0, 1] for the family of Galerkin variational integrators (issue 30):
// closed Newton–Cotes with any number of points (trapezoid, Simpson, 3/8, ...), Lobatto and Gauss.
// A rule enters the discrete Lagrangian of a polynomial Lagrangian only through its moments
// μ_n = Σ w_k c_kⁿ, and those are rational for every rule here, also where the nodes are not
// (Gauss, Lobatto beyond 3 points): τⁿ reduced modulo the rule's nodal polynomial leaves a
// polynomial of degree below the rule's exactness, integrated exactly. So every member is derived
// in exact rationals, without the nodes.

#include <simpson/precision.hpp>

#include <string>
#include <vector>

namespace simpson::verify {

enum class quadrature_family { newton_cotes, lobatto, gauss };

struct quadrature_rule {
  quadrature_family family = quadrature_family::newton_cotes;
  int points = 3;
};

/// "trapezoid", "Simpson", "3/8", "Newton–Cotes 5", "midpoint", "Gauss 2", "Lobatto 4", ...
std::string rule_name(const quadrature_rule& rule);

/// The highest degree the rule integrates exactly: points − 1 (+1 for an odd number of Newton–Cotes
/// points), 2·points − 1 (Gauss), 2·points − 3 (Lobatto).
int exactness_degree(const quadrature_rule& rule);

/// The rule's nodal polynomial (the product of τ − c_i over its nodes, up to a constant factor),
/// constant term first, with rational coefficients also where the nodes are not.
std::vector<rational> nodal_polynomial(const quadrature_rule& rule);

/// μ_0, ..., μ_max_power, exactly. Throws std::invalid_argument for fewer than 1 point (Gauss) or
/// 2 points (Newton–Cotes, Lobatto).
std::vector<rational> quadrature_moments(const quadrature_rule& rule, int max_power);

}  // namespace simpson::verify
