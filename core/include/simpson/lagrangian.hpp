#pragma once
// Beyond the paper: Lagrangians L(q, q̇) of n degrees of freedom, not necessarily separable (the
// authors' tutorial on the Lagrange top, arXiv 2512.03330), and the derivatives the steppers need,
// by Eigen's AutoDiff module: ∂L/∂q, ∂L/∂v and the Hessian blocks ∂²L/∂q², ∂²L/∂q∂v, ∂²L/∂v².
//
// A Lagrangian is any type `Lag` with
//   int dof() const;
//   template <class T> T operator()(const Eigen::Matrix<T, Eigen::Dynamic, 1>& q,
//                                   const Eigen::Matrix<T, Eigen::Dynamic, 1>& v) const;
// T is the working scalar Real or an AutoDiffScalar over it (nested, for second derivatives); the
// parameters are stored as Real and converted with T(param). Constants: T(Real(2)), or an integer
// in arithmetic (x / 2, 2 * x), or a Real constant (Real(1) / 2 * x); not T(2) (see below).
//
// Two defects of Eigen 3.4's AutoDiff, and what this header does about them:
// - Dynamic derivative vectors: a constant (T(param): no derivatives yet) in an expression of three
//   or more operands trips `aLhs.rows() == aRhs.rows()` (Eigen issue 2235; make_coherent resizes
//   the leaves of an expression after its nullary operands were sized). The derivative vectors here
//   are fixed-size, 2 · lagrangian_max_dof entries (the unused ones stay zero), so nothing is resized.
// - Nested AutoDiffScalar over a class-type scalar (mpfr, interval): `x / 2` needs int → mpfr →
//   inner AutoDiffScalar, two user-defined conversions, which C++ never chains. Not a NumTraits
//   issue (Boost's eigen.hpp changes nothing here). The operators at the end of this header take
//   the integer or floating literal to the innermost scalar explicitly; for built-in scalars
//   Eigen's own operators are used unchanged. T(2) stays an error (a constructor cannot be added).

#include <simpson/separable_system.hpp>

#include <unsupported/Eigen/AutoDiff>

#include <stdexcept>
#include <string>
#include <type_traits>

namespace simpson {

/// The most degrees of freedom the AutoDiff derivatives support (their vectors are fixed-size).
inline constexpr int lagrangian_max_dof = 4;

/// L and its first derivatives at (q, v).
template <class Real>
struct lagrangian_gradient {
  Real value;
  dense_vector<Real> dq, dv;  // ∂L/∂q, ∂L/∂v
};

/// L, its first derivatives and its Hessian blocks at (q, v); qv(i, j) = ∂²L/∂q_i∂v_j.
template <class Real>
struct lagrangian_hessian {
  Real value;
  dense_vector<Real> dq, dv;
  dense_matrix<Real> qq, qv, vv;
};

namespace detail {
template <class S>
struct is_autodiff : std::false_type {};
template <class D>
struct is_autodiff<Eigen::AutoDiffScalar<D>> : std::true_type {};

/// The scalar at the bottom of nested AutoDiffScalars.
template <class S, bool = is_autodiff<S>::value>
struct innermost_scalar {
  using type = S;
};
template <class S>
struct innermost_scalar<S, true> {
  using type = typename innermost_scalar<typename S::Scalar>::type;
};

/// An arithmetic constant as the scalar S, one constructor per level (no chained conversions).
template <class S, class A>
S from_arithmetic(A a) {
  if constexpr (is_autodiff<S>::value) {
    return S(from_arithmetic<typename S::Scalar>(a));
  } else {
    return S(a);
  }
}

/// True for an arithmetic literal A next to a nested AutoDiffScalar whose innermost scalar is a
/// class (mpfr, interval): the case Eigen's operators cannot convert.
template <class D, class A>
inline constexpr bool needs_literal_conversion_v =
    std::is_arithmetic<A>::value && is_autodiff<typename Eigen::AutoDiffScalar<D>::Scalar>::value &&
    std::is_class<typename innermost_scalar<typename Eigen::AutoDiffScalar<D>::Scalar>::type>::value;

constexpr int ad_size = 2 * lagrangian_max_dof;
template <class Real>
using ad1 = Eigen::AutoDiffScalar<Eigen::Matrix<Real, ad_size, 1>>;
template <class Real>
using ad2 = Eigen::AutoDiffScalar<Eigen::Matrix<ad1<Real>, ad_size, 1>>;

template <class Lag, class Real>
int checked_dof(const Lag& L, const dense_vector<Real>& q, const dense_vector<Real>& v, const char* who) {
  const int n = L.dof();
  if (n < 1 || n > lagrangian_max_dof) {
    throw std::invalid_argument(std::string(who) + ": L.dof() must be from 1 to " + std::to_string(lagrangian_max_dof));
  }
  if (q.size() != n || v.size() != n) throw std::invalid_argument(std::string(who) + ": q and v must have L.dof() entries");
  return n;
}
}  // namespace detail

/// L(q, v) in the working scalar.
template <class Real, class Lag>
Real lagrangian_value(const Lag& L, const dense_vector<Real>& q, const dense_vector<Real>& v) {
  detail::checked_dof(L, q, v, "simpson::lagrangian_value");
  return L(q, v);
}

/// ∂L/∂q and ∂L/∂v at (q, v) by forward AutoDiff (one pass, 2n derivative directions).
template <class Real, class Lag>
lagrangian_gradient<Real> lagrangian_gradient_at(const Lag& L, const dense_vector<Real>& q, const dense_vector<Real>& v) {
  const int n = detail::checked_dof(L, q, v, "simpson::lagrangian_gradient_at");
  using T = detail::ad1<Real>;
  Eigen::Matrix<T, Eigen::Dynamic, 1> Q(n), V(n);
  for (int i = 0; i < n; ++i) {
    Q(i) = T(q(i), detail::ad_size, i);
    V(i) = T(v(i), detail::ad_size, n + i);
  }
  const T r = L(Q, V);
  lagrangian_gradient<Real> out{r.value(), dense_vector<Real>(n), dense_vector<Real>(n)};
  for (int i = 0; i < n; ++i) {
    out.dq(i) = r.derivatives()(i);
    out.dv(i) = r.derivatives()(n + i);
  }
  return out;
}

/// The first and second derivatives at (q, v) by nested forward AutoDiff (the Hessian of L in the
/// 2n variables (q, v), cut into its blocks).
template <class Real, class Lag>
lagrangian_hessian<Real> lagrangian_hessian_at(const Lag& L, const dense_vector<Real>& q, const dense_vector<Real>& v) {
  const int n = detail::checked_dof(L, q, v, "simpson::lagrangian_hessian_at");
  using T1 = detail::ad1<Real>;
  using T2 = detail::ad2<Real>;
  const auto variable = [](const Real& value, int k) {
    T2 x(T1(value, detail::ad_size, k));  // outer derivatives zero (fixed size)
    x.derivatives()(k) = T1(Real(1));
    return x;
  };
  Eigen::Matrix<T2, Eigen::Dynamic, 1> Q(n), V(n);
  for (int i = 0; i < n; ++i) {
    Q(i) = variable(q(i), i);
    V(i) = variable(v(i), n + i);
  }
  const T2 r = L(Q, V);
  lagrangian_hessian<Real> out{r.value().value(), dense_vector<Real>(n), dense_vector<Real>(n),
                               dense_matrix<Real>(n, n), dense_matrix<Real>(n, n), dense_matrix<Real>(n, n)};
  for (int i = 0; i < n; ++i) {
    out.dq(i) = r.derivatives()(i).value();
    out.dv(i) = r.derivatives()(n + i).value();
    for (int j = 0; j < n; ++j) {
      out.qq(i, j) = r.derivatives()(i).derivatives()(j);
      out.qv(i, j) = r.derivatives()(i).derivatives()(n + j);
      out.vv(i, j) = r.derivatives()(n + i).derivatives()(n + j);
    }
  }
  return out;
}

}  // namespace simpson

// Arithmetic literals with nested AutoDiffScalars over a class-type scalar (see the top of this
// header). In Eigen's namespace so that argument-dependent lookup finds them wherever a Lagrangian
// is written; enabled only where Eigen's own operators cannot convert the literal.
namespace Eigen {
#define SIMPSON_AUTODIFF_LITERAL_OPERATOR(OP)                                                                 \
  template <class D, class A, std::enable_if_t<::simpson::detail::needs_literal_conversion_v<D, A>, int> = 0> \
  auto operator OP(const AutoDiffScalar<D>& x, A a) {                                                         \
    return x OP ::simpson::detail::from_arithmetic<typename AutoDiffScalar<D>::Scalar>(a);                    \
  }                                                                                                           \
  template <class D, class A, std::enable_if_t<::simpson::detail::needs_literal_conversion_v<D, A>, int> = 0> \
  auto operator OP(A a, const AutoDiffScalar<D>& x) {                                                         \
    return ::simpson::detail::from_arithmetic<typename AutoDiffScalar<D>::Scalar>(a) OP x;                    \
  }
SIMPSON_AUTODIFF_LITERAL_OPERATOR(+)
SIMPSON_AUTODIFF_LITERAL_OPERATOR(-)
SIMPSON_AUTODIFF_LITERAL_OPERATOR(*)
SIMPSON_AUTODIFF_LITERAL_OPERATOR(/)
#undef SIMPSON_AUTODIFF_LITERAL_OPERATOR
}  // namespace Eigen
