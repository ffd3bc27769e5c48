(* Certificate of claim interpolant-derivative: dq/dt = (1/h)[q_l (4 theta - 3) + 4 q_m (1 - 2 theta) + q_r (4 theta - 1)] = g_l (1 - theta) + g_r theta.
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

Lemma interpolant_derivative_equation_1_side_2 :
  forall h q_l q_m q_r theta : R,
  0 < h ->
  h <> 0 ->
  (((-1) * (((-4) * theta) + 1) * (/ h) * q_r) + ((-1) * (((-4) * theta) + 3) * (/ h) * q_l) + (4 * (((-2) * theta) + 1) * (/ h) * q_m))
  = ((-1) * (((((-4) * theta) + 1) * q_r) + ((((-4) * theta) + 3) * q_l) + ((-4) * (((-2) * theta) + 1) * q_m)) * (/ h)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma interpolant_derivative_equation_1_side_3 :
  forall h q_l q_m q_r theta : R,
  0 < h ->
  h <> 0 ->
  (((-1) * (((-4) * theta) + 1) * (/ h) * q_r) + ((-1) * (((-4) * theta) + 3) * (/ h) * q_l) + (4 * (((-2) * theta) + 1) * (/ h) * q_m))
  = ((-1) * (((((-4) * theta) + 1) * q_r) + ((((-4) * theta) + 3) * q_l) + ((-4) * (((-2) * theta) + 1) * q_m)) * (/ h)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma interpolant_derivative_equation_1_side_4 :
  forall h q_l q_m q_r theta : R,
  0 < h ->
  h <> 0 ->
  (((-1) * (((-4) * theta) + 1) * (/ h) * q_r) + ((-1) * (((-4) * theta) + 3) * (/ h) * q_l) + (4 * (((-2) * theta) + 1) * (/ h) * q_m))
  = (((((-1) * q_r) + ((-3) * q_l) + (4 * q_m)) * (((-1) * theta) + 1) * (/ h)) + ((-1) * (((-1) * q_l) + ((-3) * q_r) + (4 * q_m)) * (/ h) * theta)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
