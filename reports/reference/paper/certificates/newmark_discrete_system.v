(* Certificate of claim newmark-discrete-system: p_{j+1} - p_j = -m omega^2 h (q_{j+1} + q_j)/2 and (q_{j+1} - q_j)/h = (p_{j+1} + p_j)/(2m).
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

Lemma newmark_discrete_system_equation_1_side_2 :
  forall h m omega q_j q_jp1 : R,
  0 < m ->
  0 < h ->
  h <> 0 ->
  (((1/4) * (((-1) * (h ^ 2) * (omega ^ 2) * m * q_j) + ((-1) * (h ^ 2) * (omega ^ 2) * m * q_jp1) + ((-4) * m * q_j) + (4 * m * q_jp1)) * (/ h)) + ((1/4) * (((-1) * (h ^ 2) * (omega ^ 2) * m * q_j) + ((-1) * (h ^ 2) * (omega ^ 2) * m * q_jp1) + ((-4) * m * q_jp1) + (4 * m * q_j)) * (/ h)))
  = ((1/2) * (((-1) * q_j) + ((-1) * q_jp1)) * (omega ^ 2) * h * m).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma newmark_discrete_system_equation_2_side_2 :
  forall h m omega q_j q_jp1 : R,
  0 < m ->
  0 < h ->
  h <> 0 ->
  m <> 0 ->
  ((((-1) * q_j) + q_jp1) * (/ h))
  = ((1/8) * (((((-1) * (h ^ 2) * (omega ^ 2) * m * q_j) + ((-1) * (h ^ 2) * (omega ^ 2) * m * q_jp1) + ((-4) * m * q_j) + (4 * m * q_jp1)) * (/ h)) + ((-1) * (((-1) * (h ^ 2) * (omega ^ 2) * m * q_j) + ((-1) * (h ^ 2) * (omega ^ 2) * m * q_jp1) + ((-4) * m * q_jp1) + (4 * m * q_j)) * (/ h))) * (/ m)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
