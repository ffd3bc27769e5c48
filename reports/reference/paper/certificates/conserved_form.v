(* Certificate of claim conserved-form: When alpha = delta, eta = 0 and Q_c(p, q) = gamma p^2/2 - beta q^2/2 is conserved, up to a multiplicative constant.
   Written by simpson-verify from the expressions its GiNaC kernel proved; check with coqc. *)
Require Import Reals Field Lra Psatz.
Open Scope R_scope.

(* field leaves side conditions X <> 0 in its own normal form: each is a hypothesis up to ring,
   a positive hypothesis, or a power of one. *)
Ltac nonzero :=
  first [ assumption
        | match goal with
          | [ H : ?Y <> 0 |- ?X <> 0 ] => replace X with Y by ring; exact H
          | [ H : 0 < ?Y |- ?X <> 0 ] => replace X with Y by ring; apply Rgt_not_eq; exact H
          end
        | apply pow_nonzero; nonzero ].
(* Not stated: conserved_form_derived, whose two sides GiNaC evaluates to one expression (X = X checks nothing). *)

Lemma conserved_form_conserved :
  forall alpha beta p q : R,
  beta <> 0 ->
  (((-1/2) * ((((((-1) * (alpha ^ 2)) + 1) * (/ beta) * p) + ((-1) * alpha * q)) ^ 2) * beta) + ((-1/2) * ((((-1) * alpha * p) + ((-1) * beta * q)) ^ 2) * (((-1) * (alpha ^ 2)) + 1) * (/ beta)) + ((1/2) * (((-1) * (alpha ^ 2)) + 1) * (/ beta) * (p ^ 2)) + ((1/2) * (q ^ 2) * beta))
  = 0.
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
