(* Certificate of claim truncation-1440: T_h(q_j) = omega^6 h^4 q_j/1440 + O(h^6).
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

Lemma truncation_1440_printed_taylor_remainder :
  forall h m omega p_j q_j : R,
  0 < m ->
  0 < h ->
  h <> 0 ->
  m <> 0 ->
  omega <> 0 ->
  ((-1/967680) * (((((((-1) * (h ^ 8) * (omega ^ 8)) + ((-1680) * (h ^ 4) * (omega ^ 4)) + (-40320) + (20160 * (h ^ 2) * (omega ^ 2)) + (56 * (h ^ 6) * (omega ^ 6))) * q_j) + ((-8) * (((-1) * (h ^ 7) * (omega ^ 7)) + ((-840) * (h ^ 3) * (omega ^ 3)) + (42 * (h ^ 5) * (omega ^ 5)) + (5040 * h * omega)) * (/ m) * (/ omega) * p_j)) * (h ^ 2) * (omega ^ 2)) + ((((((-1) * (h ^ 8) * (omega ^ 8)) + ((-1680) * (h ^ 4) * (omega ^ 4)) + (-40320) + (20160 * (h ^ 2) * (omega ^ 2)) + (56 * (h ^ 6) * (omega ^ 6))) * q_j) + (8 * (((-1) * (h ^ 7) * (omega ^ 7)) + ((-840) * (h ^ 3) * (omega ^ 3)) + (42 * (h ^ 5) * (omega ^ 5)) + (5040 * h * omega)) * (/ m) * (/ omega) * p_j)) * (h ^ 2) * (omega ^ 2)) + ((-887040) * (h ^ 2) * (omega ^ 2) * q_j) + (1935360 * q_j) + (40320 * (h ^ 4) * (omega ^ 4) * q_j) + (48 * (((-1) * (h ^ 8) * (omega ^ 8)) + ((-1680) * (h ^ 4) * (omega ^ 4)) + (-40320) + (20160 * (h ^ 2) * (omega ^ 2)) + (56 * (h ^ 6) * (omega ^ 6))) * q_j)) * (/ (h ^ 2)))
  = (((-1/483840) * (((-1) * (h ^ 2) * (omega ^ 10) * q_j) + (32 * (omega ^ 8) * q_j)) * (h ^ 6)) + ((1/1440) * (h ^ 4) * (omega ^ 6) * q_j)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
