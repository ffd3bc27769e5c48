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

Lemma gear_partials_printed :
  forall h : R,
  0 < h ->
  h <> 0 ->
  (4 * (/ h))
  = (4 * (/ h)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma gear_partials_core :
  forall h : R,
  0 < h ->
  h <> 0 ->
  (4 * (/ h))
  = (4 * (/ h)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma gear_partials_printed_2 :
  0
  = 0.
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma gear_partials_core_2 :
  0
  = 0.
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma gear_partials_printed_3 :
  forall h : R,
  0 < h ->
  h <> 0 ->
  ((-4) * (/ h))
  = ((-4) * (/ h)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma gear_partials_core_3 :
  forall h : R,
  0 < h ->
  h <> 0 ->
  ((-4) * (/ h))
  = ((-4) * (/ h)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
