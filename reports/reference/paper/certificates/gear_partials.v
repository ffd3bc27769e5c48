(* Certificate of claim gear-partials: dg_l/dq_m = 4/h, dg_m/dq_m = 0 and dg_r/dq_m = -4/h.
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
(* Not stated: gear_partials_printed, gear_partials_core, gear_partials_printed_2, gear_partials_core_2, gear_partials_printed_3, gear_partials_core_3, gear_partials_printed_increment_2, whose two sides GiNaC evaluates to one expression (X = X checks nothing). *)

Lemma gear_partials_printed_increment :
  forall e h q_l q_m q_r : R,
  0 < h ->
  h <> 0 ->
  (((((-1) * q_r) + ((-3) * q_l) + (4 * e) + (4 * q_m)) * (/ h)) + ((-1) * (((-1) * q_r) + ((-3) * q_l) + (4 * q_m)) * (/ h)))
  = (4 * (/ h) * e).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma gear_partials_printed_increment_3 :
  forall e h q_l q_m q_r : R,
  0 < h ->
  h <> 0 ->
  (((((-1) * q_l) + ((-3) * q_r) + (4 * q_m)) * (/ h)) + ((-1) * (((-1) * q_l) + ((-3) * q_r) + (4 * e) + (4 * q_m)) * (/ h)))
  = ((-4) * (/ h) * e).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
