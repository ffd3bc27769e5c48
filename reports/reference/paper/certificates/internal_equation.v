(* Certificate of claim internal-equation: dL_h/dq_m = 0 is m (4/h^2)(q_l - 2 q_m + q_r) + dV/dq(q_m) = 0.
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

Lemma internal_equation_stationary :
  forall (dV : R -> R) (h m q_l q_m q_r : R),
  0 < m ->
  0 < h ->
  h <> 0 ->
  ((2/3) * (((-1) * (dV q_m)) + (4 * (((-1) * q_l) + ((-1) * q_r) + (2 * q_m)) * (/ (h ^ 2)) * m)) * h)
  = (((-2/3) * (dV q_m) * h) + ((2/3) * (((((-1) * q_l) + ((-3) * q_r) + (4 * q_m)) * (/ (h ^ 2))) + ((((-1) * q_r) + ((-3) * q_l) + (4 * q_m)) * (/ (h ^ 2)))) * h * m)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
