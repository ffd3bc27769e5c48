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
(* Not stated: newmark_matrix_printed_11, newmark_matrix_printed_12, newmark_matrix_printed_21, newmark_matrix_printed_22, newmark_matrix_core_11, newmark_matrix_core_12, newmark_matrix_core_21, newmark_matrix_core_22, whose two sides GiNaC evaluates to one expression (X = X checks nothing). *)

Lemma newmark_matrix_printed_momentum_left :
  forall h m omega p_j q_j : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-4)) <> 0 ->
  h <> 0 ->
  m <> 0 ->
  ((-1/4) * (((((((-1) * (h ^ 2) * (omega ^ 2)) + 4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * q_j) + (4 * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * (/ m) * h * p_j)) * (h ^ 2) * (omega ^ 2) * m) + ((-1) * (h ^ 2) * (omega ^ 2) * m * q_j) + (4 * (((((-1) * (h ^ 2) * (omega ^ 2)) + 4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * q_j) + (4 * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * (/ m) * h * p_j)) * m) + (4 * m * q_j)) * (/ h))
  = p_j.
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma newmark_matrix_printed_momentum_right :
  forall h m omega p_j q_j : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-4)) <> 0 ->
  h <> 0 ->
  m <> 0 ->
  ((1/4) * (((((((-1) * (h ^ 2) * (omega ^ 2)) + 4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * q_j) + (4 * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * (/ m) * h * p_j)) * (h ^ 2) * (omega ^ 2) * m) + ((-1) * (h ^ 2) * (omega ^ 2) * m * q_j) + ((-4) * (((((-1) * (h ^ 2) * (omega ^ 2)) + 4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * q_j) + (4 * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * (/ m) * h * p_j)) * m) + ((-4) * m * q_j)) * (/ h))
  = (((-1) * (((-1) * (h ^ 2) * (omega ^ 2)) + 4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * p_j) + (4 * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * (omega ^ 2) * h * m * q_j)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma newmark_matrix_core_momentum_left :
  forall h m omega p_j q_j : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-4)) <> 0 ->
  h <> 0 ->
  m <> 0 ->
  ((-1/4) * (((((((-1) * (h ^ 2) * (omega ^ 2)) + 4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * q_j) + (4 * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * (/ m) * h * p_j)) * (h ^ 2) * (omega ^ 2) * m) + ((-1) * (h ^ 2) * (omega ^ 2) * m * q_j) + (4 * (((((-1) * (h ^ 2) * (omega ^ 2)) + 4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * q_j) + (4 * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * (/ m) * h * p_j)) * m) + (4 * m * q_j)) * (/ h))
  = p_j.
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma newmark_matrix_core_momentum_right :
  forall h m omega p_j q_j : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-4)) <> 0 ->
  h <> 0 ->
  m <> 0 ->
  ((1/4) * (((((((-1) * (h ^ 2) * (omega ^ 2)) + 4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * q_j) + (4 * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * (/ m) * h * p_j)) * (h ^ 2) * (omega ^ 2) * m) + ((-1) * (h ^ 2) * (omega ^ 2) * m * q_j) + ((-4) * (((((-1) * (h ^ 2) * (omega ^ 2)) + 4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * q_j) + (4 * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * (/ m) * h * p_j)) * m) + ((-4) * m * q_j)) * (/ h))
  = (((-1) * (((-1) * (h ^ 2) * (omega ^ 2)) + 4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * p_j) + (4 * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * (omega ^ 2) * h * m * q_j)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
