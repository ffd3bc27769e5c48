(* Certificate of claim conclusion-fourth-order: The method is fourth order accurate for state and momentum.
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

Lemma conclusion_fourth_order_entry_11 :
  forall h omega : R,
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) <> 0 ->
  (((-1/24) * (h ^ 4) * (omega ^ 4)) + ((1/2) * (((-1) * (h ^ 4) * (omega ^ 4)) + (-48) + (22 * (h ^ 2) * (omega ^ 2))) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)))) + ((1/2) * (h ^ 2) * (omega ^ 2)) + (-1))
  = ((1/24) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24))) * (h ^ 6) * (omega ^ 6)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma conclusion_fourth_order_entry_12 :
  forall h m omega : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) <> 0 ->
  (((-1/120) * (((-1) * (h ^ 5) * (omega ^ 5)) + ((-120) * h * omega) + (20 * (h ^ 3) * (omega ^ 3))) * m * omega) + ((1/12) * (((-1) * (h ^ 2) * (omega ^ 2)) + 12) * (((-1) * (h ^ 2) * (omega ^ 2)) + 24) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24))) * (omega ^ 2) * h * m))
  = ((1/120) * (((-1) * (h ^ 2) * (omega ^ 8) * m) + (6 * (omega ^ 6) * m)) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24))) * (h ^ 5)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma conclusion_fourth_order_entry_21 :
  forall h m omega : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) <> 0 ->
  m <> 0 ->
  omega <> 0 ->
  (((-3) * (((-1) * (h ^ 2) * (omega ^ 2)) + 8) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24))) * (/ m) * h) + ((1/120) * (((-1) * (h ^ 5) * (omega ^ 5)) + ((-120) * h * omega) + (20 * (h ^ 3) * (omega ^ 3))) * (/ m) * (/ omega)))
  = ((-1/120) * (((-1) * (h ^ 2) * (omega ^ 6)) + ((-4) * (omega ^ 4))) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24))) * (/ m) * (h ^ 5)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma conclusion_fourth_order_entry_22 :
  forall h omega : R,
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) <> 0 ->
  (((-1/24) * (h ^ 4) * (omega ^ 4)) + ((1/2) * (((-1) * (h ^ 4) * (omega ^ 4)) + (-48) + (22 * (h ^ 2) * (omega ^ 2))) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)))) + ((1/2) * (h ^ 2) * (omega ^ 2)) + (-1))
  = ((1/24) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24))) * (h ^ 6) * (omega ^ 6)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
