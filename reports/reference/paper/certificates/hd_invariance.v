(* Certificate of claim hd-invariance: H_d(p_{j+1}, q_{j+1}) = H_d(p_j, q_j).
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

Lemma hd_invariance_conserved :
  forall h m omega p q : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) <> 0 ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + 8) <> 0 ->
  m <> 0 ->
  (((1/288) * ((((((-1) * (h ^ 2) * (omega ^ 2)) + 12) * (((-1) * (h ^ 2) * (omega ^ 2)) + 24) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24))) * (omega ^ 2) * h * m * q) + (6 * (((-1) * (h ^ 4) * (omega ^ 4)) + (-48) + (22 * (h ^ 2) * (omega ^ 2))) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24))) * p)) ^ 2) * (/ m)) + ((1/288) * ((((((-1) * (h ^ 4) * (omega ^ 4)) + (-48) + (22 * (h ^ 2) * (omega ^ 2))) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24))) * q) + ((-6) * (((-1) * (h ^ 2) * (omega ^ 2)) + 8) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24))) * (/ m) * h * p)) ^ 2) * (((-1) * (h ^ 2) * (omega ^ 2)) + 12) * (((-1) * (h ^ 2) * (omega ^ 2)) + 24) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 8)) * (omega ^ 2) * m))
  = (((1/2) * (/ m) * (p ^ 2)) + ((1/72) * (((-1) * (h ^ 2) * (omega ^ 2)) + 12) * (((-1) * (h ^ 2) * (omega ^ 2)) + 24) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 8)) * (omega ^ 2) * (q ^ 2) * m)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
