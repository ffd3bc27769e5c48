(* Certificate of claim gamma-singular: This expression vanishes when alpha delta - beta gamma = 1: the system Gamma is singular there, so a nonzero quadratic form is conserved.
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

Lemma gamma_singular_derived :
  forall alpha beta gamma : R,
  alpha <> 0 ->
  (((-1/2) * ((((((((-1) * beta * gamma) + (-1)) ^ 2) * (/ (alpha ^ 2))) + (-1)) * alpha * beta) + ((((-1) * beta * gamma) + (-1)) * (/ alpha) * (beta ^ 2) * gamma)) * alpha * gamma) + ((-1/2) * ((((((((-1) * beta * gamma) + (-1)) ^ 2) * (/ (alpha ^ 2))) + (-1)) * beta * gamma) + ((-1) * ((((-1) * beta * gamma) + (-1)) ^ 2) * (/ (alpha ^ 2)) * beta * gamma)) * (((-1) * (alpha ^ 2)) + 1)) + ((-1/2) * (((((-1) * beta * gamma) + (-1)) * (beta ^ 2)) + ((beta ^ 3) * gamma)) * (gamma ^ 2)))
  = 0.
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
