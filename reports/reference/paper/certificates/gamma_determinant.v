(* Certificate of claim gamma-determinant: det Gamma = (alpha delta - beta gamma - 1)(1 - alpha - delta + alpha delta - beta gamma)(1 + alpha + delta + alpha delta - beta gamma).
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
(* Refuted by GiNaC, negated in the claim's _refuted.v: determinant. *)

Lemma gamma_determinant_derived :
  forall alpha beta delta gamma : R,
  (((-1/4) * (alpha ^ 2) * (delta ^ 2)) + ((-1/4) * (alpha ^ 3) * delta) + ((-1/4) * (beta ^ 3) * (gamma ^ 3)) + ((-1/4) * (delta ^ 3) * alpha) + ((-3/4) * (alpha ^ 2) * (delta ^ 2) * beta * gamma) + ((1/4) * (alpha ^ 2) * beta * gamma) + ((1/4) * (alpha ^ 2)) + ((1/4) * (alpha ^ 3) * (delta ^ 3)) + ((1/4) * (beta ^ 2) * (gamma ^ 2)) + ((1/4) * (delta ^ 2) * beta * gamma) + ((1/4) * (delta ^ 2)) + ((1/4) * alpha * delta) + ((1/4) * beta * gamma) + ((3/4) * (beta ^ 2) * (gamma ^ 2) * alpha * delta) + (-1/4))
  = ((-1/4) * (((-1) * alpha * delta) + ((-1) * alpha) + ((-1) * delta) + (-1) + (beta * gamma)) * (((-1) * alpha * delta) + (-1) + (beta * gamma) + alpha + delta) * (((-1) * alpha * delta) + (beta * gamma) + 1)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
