(* Certificate of claim simpson-lagrangian: With Simpson's formula and the quadratic interpolant, L_h = (m h/12)(g_l^2 + 4 g_m^2 + g_r^2) - (h/6)(V(q_l) + 4 V(q_m) + V(q_r)).
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

Lemma simpson_lagrangian_lagrangian :
  forall (V : R -> R) (h m q_l q_m q_r : R),
  0 < m ->
  0 < h ->
  h <> 0 ->
  (((1/12) * ((((((-1) * (/ h) * q_l) + ((-3) * (/ h) * q_r) + (4 * (/ h) * q_m)) ^ 2) * m) + ((-2) * (V q_r))) * h) + ((1/12) * ((((((-1) * (/ h) * q_r) + ((-3) * (/ h) * q_l) + (4 * (/ h) * q_m)) ^ 2) * m) + ((-2) * (V q_l))) * h) + ((1/3) * ((((((-1) * (/ h) * q_l) + ((/ h) * q_r)) ^ 2) * m) + ((-2) * (V q_m))) * h))
  = (((1/12) * ((((((-1) * q_l) + ((-3) * q_r) + (4 * q_m)) ^ 2) * (/ (h ^ 2))) + (((((-1) * q_r) + ((-3) * q_l) + (4 * q_m)) ^ 2) * (/ (h ^ 2))) + (4 * ((((-1) * q_l) + q_r) ^ 2) * (/ (h ^ 2)))) * h * m) + ((1/6) * (((-1) * (V q_l)) + ((-1) * (V q_r)) + ((-4) * (V q_m))) * h)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
