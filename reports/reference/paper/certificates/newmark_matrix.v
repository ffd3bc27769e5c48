(* Certificate of claim newmark-matrix: The system is (p_{j+1}, q_{j+1}) = Phi (p_j, q_j) with Phi = 1/(1 + omega^2 h^2/4) ((1 - omega^2 h^2/4, -m omega^2 h), (h/m, 1 - omega^2 h^2/4)).
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

Lemma newmark_matrix_printed_11 :
  forall h omega : R,
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-4)) <> 0 ->
  ((-1) * (((-1) * (h ^ 2) * (omega ^ 2)) + 4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))))
  = ((-1) * (((-1) * (h ^ 2) * (omega ^ 2)) + 4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4)))).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma newmark_matrix_printed_12 :
  forall h m omega : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-4)) <> 0 ->
  (4 * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * (omega ^ 2) * h * m)
  = (4 * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * (omega ^ 2) * h * m).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma newmark_matrix_printed_21 :
  forall h m omega : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-4)) <> 0 ->
  m <> 0 ->
  ((-4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * (/ m) * h)
  = ((-4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * (/ m) * h).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma newmark_matrix_printed_22 :
  forall h omega : R,
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-4)) <> 0 ->
  ((-1) * (((-1) * (h ^ 2) * (omega ^ 2)) + 4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))))
  = ((-1) * (((-1) * (h ^ 2) * (omega ^ 2)) + 4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4)))).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma newmark_matrix_core_11 :
  forall h omega : R,
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-4)) <> 0 ->
  ((-1) * (((-1) * (h ^ 2) * (omega ^ 2)) + 4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))))
  = ((-1) * (((-1) * (h ^ 2) * (omega ^ 2)) + 4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4)))).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma newmark_matrix_core_12 :
  forall h m omega : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-4)) <> 0 ->
  (4 * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * (omega ^ 2) * h * m)
  = (4 * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * (omega ^ 2) * h * m).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma newmark_matrix_core_21 :
  forall h m omega : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-4)) <> 0 ->
  m <> 0 ->
  ((-4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * (/ m) * h)
  = ((-4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * (/ m) * h).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma newmark_matrix_core_22 :
  forall h omega : R,
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-4)) <> 0 ->
  ((-1) * (((-1) * (h ^ 2) * (omega ^ 2)) + 4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))))
  = ((-1) * (((-1) * (h ^ 2) * (omega ^ 2)) + 4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4)))).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
