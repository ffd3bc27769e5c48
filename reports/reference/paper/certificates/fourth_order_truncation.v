(* Certificate of claim fourth-order-truncation: The numerical scheme is fourth order accurate in the sense of the truncation error.
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

Lemma fourth_order_truncation_next_coefficient :
  forall h omega : R,
  0 < h ->
  h <> 0 ->
  (((1/24) * (omega ^ 2)) + (/ (h ^ 2)))
  = ((-1/24) * (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) * (/ (h ^ 2))).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma fourth_order_truncation_taylor_order :
  forall h omega q_j : R,
  0 < h ->
  h <> 0 ->
  (((-1/24) * (h ^ 2) * (omega ^ 4) * q_j) + ((1/1814400) * (((((-1) * (h ^ 10) * (omega ^ 10)) + ((-1814400) * (h ^ 2) * (omega ^ 2)) + ((-5040) * (h ^ 6) * (omega ^ 6)) + (151200 * (h ^ 4) * (omega ^ 4)) + (90 * (h ^ 8) * (omega ^ 8)) + 3628800) * q_j) + ((-3628800) * q_j)) * (/ (h ^ 2))) + ((1/43545600) * (((((-1) * (h ^ 10) * (omega ^ 10)) + ((-1814400) * (h ^ 2) * (omega ^ 2)) + ((-5040) * (h ^ 6) * (omega ^ 6)) + (151200 * (h ^ 4) * (omega ^ 4)) + (90 * (h ^ 8) * (omega ^ 8)) + 3628800) * q_j) + (39916800 * q_j)) * (omega ^ 2)))
  = ((1/43545600) * (((-1) * (h ^ 6) * (omega ^ 12) * q_j) + ((-2880) * (h ^ 2) * (omega ^ 8) * q_j) + (30240 * (omega ^ 6) * q_j) + (66 * (h ^ 4) * (omega ^ 10) * q_j)) * (h ^ 4)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
