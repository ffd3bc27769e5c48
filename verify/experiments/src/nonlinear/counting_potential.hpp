#pragma once
// The work of a nonlinear run in force evaluations: a potential that counts the calls of ∇V and ∇²V
// its steps make, as they are written (no call is cached or merged), so that error can be set against
// work that does not depend on the machine or the implementation's speed.

#include <utility>  // std::declval, std::move

namespace simpson::verify::detail {

/// How many times a run evaluated the force ∇V and the Hessian ∇²V.
struct evaluation_count {
  long long gradients = 0, hessians = 0;
};

/// `Potential` with its ∇V and ∇²V calls counted into an evaluation_count (V itself, used only for the
/// energy that the run watches, is not counted). The nonlinear problems and the FPU chain count with it.
template <class Potential>
class counting_potential {
 public:
  counting_potential(Potential inner, evaluation_count& count) : inner_(std::move(inner)), count_(&count) {}
  template <class Vector>
  auto value(const Vector& q) const {
    return inner_.value(q);
  }
  template <class Vector>
  auto gradient(const Vector& q) const {
    ++count_->gradients;
    return inner_.gradient(q);
  }
  template <class Vector>
  auto hessian(const Vector& q) const {
    ++count_->hessians;
    return inner_.hessian(q);
  }
  // The split a trigonometric step takes (trigonometric_step.hpp), where the potential has one: the
  // stiff part's frequency and projector (no force evaluated), and ∇U, the slow part's gradient, counted
  // as one force evaluation.
  // Each declared only where Potential has it, so that has_stiff_split (integration_methods.hpp) sees
  // through the count.
  template <class P = Potential>
  auto stiff_frequency() const -> decltype(std::declval<const P&>().stiff_frequency()) {
    return inner_.stiff_frequency();
  }
  template <class Vector>
  auto stiff_projection(const Vector& v) const {
    return inner_.stiff_projection(v);
  }
  template <class Vector>
  auto slow_gradient(const Vector& q) const {
    ++count_->gradients;
    return inner_.slow_gradient(q);
  }

 private:
  Potential inner_;
  evaluation_count* count_;
};

}  // namespace simpson::verify::detail
