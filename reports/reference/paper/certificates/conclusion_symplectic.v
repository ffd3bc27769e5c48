(* Certificate of claim conclusion-symplectic: The method is symplectic.
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
(* Not stated: conclusion_symplectic_symplectic_11, conclusion_symplectic_symplectic_22, whose two sides GiNaC evaluates to one expression (X = X checks nothing). *)

Lemma conclusion_symplectic_symplectic_12 :
  forall h omega : R,
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) <> 0 ->
  (((1/4) * ((((-1) * (h ^ 4) * (omega ^ 4)) + (-48) + (22 * (h ^ 2) * (omega ^ 2))) ^ 2) * (/ ((((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) ^ 2))) + ((1/4) * (((-1) * (h ^ 2) * (omega ^ 2)) + 12) * (((-1) * (h ^ 2) * (omega ^ 2)) + 24) * (((-1) * (h ^ 2) * (omega ^ 2)) + 8) * (/ ((((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) ^ 2)) * (h ^ 2) * (omega ^ 2)))
  = 1.
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma conclusion_symplectic_symplectic_21 :
  forall h omega : R,
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) <> 0 ->
  (((-1/4) * ((((-1) * (h ^ 4) * (omega ^ 4)) + (-48) + (22 * (h ^ 2) * (omega ^ 2))) ^ 2) * (/ ((((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) ^ 2))) + ((-1/4) * (((-1) * (h ^ 2) * (omega ^ 2)) + 12) * (((-1) * (h ^ 2) * (omega ^ 2)) + 24) * (((-1) * (h ^ 2) * (omega ^ 2)) + 8) * (/ ((((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) ^ 2)) * (h ^ 2) * (omega ^ 2)))
  = (-1).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
