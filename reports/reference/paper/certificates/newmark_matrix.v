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
(* Not stated: newmark_matrix_printed_11, newmark_matrix_printed_12, newmark_matrix_printed_22, whose two sides GiNaC evaluates to one expression (X = X checks nothing). *)

Lemma newmark_matrix_printed_21 :
  forall h m omega : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2) * m) + ((-4) * m)) <> 0 ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-4)) <> 0 ->
  m <> 0 ->
  ((-4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * (/ m) * h)
  = ((-4) * (/ (((-1) * (h ^ 2) * (omega ^ 2) * m) + ((-4) * m))) * h).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma newmark_matrix_derived_momentum_left :
  forall h m omega p_l q_l : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2) * m) + ((-4) * m)) <> 0 ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-4)) <> 0 ->
  h <> 0 ->
  m <> 0 ->
  (((-1) * (((((-1) * (h ^ 2) * (omega ^ 2) * m * q_l) + (4 * h * p_l) + (4 * m * q_l)) * (/ (((-1) * (h ^ 2) * (omega ^ 2) * m) + ((-4) * m)))) + q_l) * (/ h) * m) + ((-1/4) * (((((-1) * (h ^ 2) * (omega ^ 2) * m * q_l) + (4 * h * p_l) + (4 * m * q_l)) * (/ (((-1) * (h ^ 2) * (omega ^ 2) * m) + ((-4) * m)))) + ((-1) * q_l)) * (omega ^ 2) * h * m))
  = p_l.
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma newmark_matrix_derived_momentum_right :
  forall h m omega p_l q_l : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2) * m) + ((-4) * m)) <> 0 ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-4)) <> 0 ->
  h <> 0 ->
  m <> 0 ->
  (((-1) * (((((-1) * (h ^ 2) * (omega ^ 2) * m * q_l) + (4 * h * p_l) + (4 * m * q_l)) * (/ (((-1) * (h ^ 2) * (omega ^ 2) * m) + ((-4) * m)))) + q_l) * (/ h) * m) + ((1/4) * (((((-1) * (h ^ 2) * (omega ^ 2) * m * q_l) + (4 * h * p_l) + (4 * m * q_l)) * (/ (((-1) * (h ^ 2) * (omega ^ 2) * m) + ((-4) * m)))) + ((-1) * q_l)) * (omega ^ 2) * h * m))
  = ((-1) * (((-1) * (h ^ 2) * (omega ^ 2) * p_l) + ((-4) * (omega ^ 2) * h * m * q_l) + (4 * p_l)) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4)))).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
