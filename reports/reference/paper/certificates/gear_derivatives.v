(* Certificate of claim gear-derivatives: g_l = dq/dt(0) = (-3 q_l + 4 q_m - q_r)/h, g_r = dq/dt(h) = (q_l - 4 q_m + 3 q_r)/h.
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

Lemma gear_derivatives_equation_1_side_3 :
  forall h q_l q_m q_r : R,
  0 < h ->
  h <> 0 ->
  (((-1) * (/ h) * q_r) + ((-3) * (/ h) * q_l) + (4 * (/ h) * q_m))
  = ((((-1) * q_r) + ((-3) * q_l) + (4 * q_m)) * (/ h)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma gear_derivatives_equation_2_side_3 :
  forall h q_l q_m q_r : R,
  0 < h ->
  h <> 0 ->
  (((-4) * (/ h) * q_m) + ((/ h) * q_l) + (3 * (/ h) * q_r))
  = ((-1) * (((-1) * q_l) + ((-3) * q_r) + (4 * q_m)) * (/ h)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
