(* Certificate of claim novelty-prior-work: We propose a variational symplectic numerical method for the time integration of dynamical systems issued from the least action principle.
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
(* Not stated: novelty_prior_work_entry_11, novelty_prior_work_entry_22, whose two sides GiNaC evaluates to one expression (X = X checks nothing). *)

Lemma novelty_prior_work_entry_12 :
  forall h m omega : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) <> 0 ->
  ((1/12) * (((-1) * (h ^ 2) * (omega ^ 2)) + 12) * (((-1) * (h ^ 2) * (omega ^ 2)) + 24) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24))) * (omega ^ 2) * h * m)
  = ((-1/12) * (((-1) * (h ^ 5) * (omega ^ 6) * m) + ((-288) * (omega ^ 2) * h * m) + (36 * (h ^ 3) * (omega ^ 4) * m)) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)))).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma novelty_prior_work_entry_21 :
  forall h m omega : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) <> 0 ->
  m <> 0 ->
  ((-3) * (((-1) * (h ^ 2) * (omega ^ 2)) + 8) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24))) * (/ m) * h)
  = ((-3) * (((-1) * (h ^ 3) * (omega ^ 2)) + (8 * h)) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24))) * (/ m)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
