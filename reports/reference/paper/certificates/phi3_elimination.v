(* Certificate of claim phi3-elimination: Eliminating q_{j-1} between the two momentum relations with (schema-ordre-3) gives y_{j+1} = Phi_3 y_j with Phi_3 as printed.
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
(* Not stated: phi3_elimination_printed_11, phi3_elimination_printed_22, whose two sides GiNaC evaluates to one expression (X = X checks nothing). *)

Lemma phi3_elimination_printed_12 :
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

Lemma phi3_elimination_printed_21 :
  forall h m omega : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2) * m) + ((-24) * m)) <> 0 ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) <> 0 ->
  m <> 0 ->
  ((-3) * (((-1) * (h ^ 2) * (omega ^ 2)) + 8) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24))) * (/ m) * h)
  = ((-3) * (((-1) * (h ^ 3) * (omega ^ 2)) + (8 * h)) * (/ (((-1) * (h ^ 2) * (omega ^ 2) * m) + ((-24) * m)))).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma phi3_elimination_derived_momentum_left :
  forall h m omega p_l q_l : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2) * m) + ((-24) * m)) <> 0 ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) <> 0 ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + 8) <> 0 ->
  h <> 0 ->
  m <> 0 ->
  ((1/6) * (((((((-1) * (h ^ 2) * (omega ^ 2)) + 22) * q_l) + ((((-1) * (h ^ 4) * (omega ^ 4) * m * q_l) + ((-48) * h * p_l) + ((-48) * m * q_l) + (22 * (h ^ 2) * (omega ^ 2) * m * q_l) + (6 * (h ^ 3) * (omega ^ 2) * p_l)) * (/ (((-1) * (h ^ 2) * (omega ^ 2) * m) + ((-24) * m))))) * (omega ^ 2) * h * m) + (24 * (((((-1) * (h ^ 4) * (omega ^ 4) * m * q_l) + ((-48) * h * p_l) + ((-48) * m * q_l) + (22 * (h ^ 2) * (omega ^ 2) * m * q_l) + (6 * (h ^ 3) * (omega ^ 2) * p_l)) * (/ (((-1) * (h ^ 2) * (omega ^ 2) * m) + ((-24) * m)))) + ((-2) * q_l)) * (/ h) * m)) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 8)))
  = p_l.
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma phi3_elimination_derived_momentum_right :
  forall h m omega p_l q_l : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2) * m) + ((-24) * m)) <> 0 ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) <> 0 ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + 8) <> 0 ->
  h <> 0 ->
  m <> 0 ->
  ((-1/12) * (((((((-1) * (h ^ 2) * (omega ^ 2)) + 22) * (((-1) * (h ^ 4) * (omega ^ 4) * m * q_l) + ((-48) * h * p_l) + ((-48) * m * q_l) + (22 * (h ^ 2) * (omega ^ 2) * m * q_l) + (6 * (h ^ 3) * (omega ^ 2) * p_l)) * (/ (((-1) * (h ^ 2) * (omega ^ 2) * m) + ((-24) * m)))) + (4 * q_l)) * (omega ^ 2) * h * m) + ((-48) * (((((-1) * (h ^ 4) * (omega ^ 4) * m * q_l) + ((-48) * h * p_l) + ((-48) * m * q_l) + (22 * (h ^ 2) * (omega ^ 2) * m * q_l) + (6 * (h ^ 3) * (omega ^ 2) * p_l)) * (/ (((-1) * (h ^ 2) * (omega ^ 2) * m) + ((-24) * m)))) + ((-2) * q_l)) * (/ h) * m)) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 8)))
  = ((-1/12) * (((-1) * (h ^ 5) * (omega ^ 6) * m * q_l) + ((-132) * (h ^ 2) * (omega ^ 2) * p_l) + ((-288) * (omega ^ 2) * h * m * q_l) + (288 * p_l) + (36 * (h ^ 3) * (omega ^ 4) * m * q_l) + (6 * (h ^ 4) * (omega ^ 4) * p_l)) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)))).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
