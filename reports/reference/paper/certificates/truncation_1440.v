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
  forall h omega q_j : R,
  0 < h ->
  h <> 0 ->
  (((-1/24) * (h ^ 2) * (omega ^ 4) * q_j) + ((1/360) * (((((-1) * (h ^ 6) * (omega ^ 6)) + ((-360) * (h ^ 2) * (omega ^ 2)) + (30 * (h ^ 4) * (omega ^ 4)) + 720) * q_j) + ((-720) * q_j)) * (/ (h ^ 2))) + ((1/8640) * (((((-1) * (h ^ 6) * (omega ^ 6)) + ((-360) * (h ^ 2) * (omega ^ 2)) + (30 * (h ^ 4) * (omega ^ 4)) + 720) * q_j) + (7920 * q_j)) * (omega ^ 2)))
  = (((-1/8640) * (h ^ 6) * (omega ^ 8) * q_j) + ((1/1440) * (h ^ 4) * (omega ^ 6) * q_j)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
