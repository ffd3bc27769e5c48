(* Certificate of claim reduced-lagrangian: With q_m eliminated, L_h^r = 1/(1 - omega^2 h^2/8) [m h/2 ((q_r - q_l)/h)^2 - (h/2) m omega^2 ((22 - h^2 omega^2)/48 (q_l^2 + q_r^2) + q_l q_r/12)].
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

Lemma reduced_lagrangian_identity :
  forall h m omega q_l q_r : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + 8) <> 0 ->
  h <> 0 ->
  ((1/12) * (((((((-1) * (h ^ 2) * (omega ^ 2)) + 22) * (((-1) * (q_l ^ 2)) + ((-1) * (q_r ^ 2)))) + ((-4) * q_l * q_r)) * (omega ^ 2) * h * m) + (48 * ((((-1) * q_l) + q_r) ^ 2) * (/ h) * m)) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 8)))
  = (((1/12) * ((((((-1) * q_l) + ((-16) * (((-1) * q_l) + ((-1) * q_r)) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 8))) + ((-3) * q_r)) ^ 2) * (/ (h ^ 2))) + (((((-1) * q_r) + ((-16) * (((-1) * q_l) + ((-1) * q_r)) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 8))) + ((-3) * q_l)) ^ 2) * (/ (h ^ 2))) + (4 * ((((-1) * q_l) + q_r) ^ 2) * (/ (h ^ 2)))) * h * m) + ((1/12) * (((-1) * (omega ^ 2) * (q_l ^ 2) * m) + ((-1) * (omega ^ 2) * (q_r ^ 2) * m) + ((-64) * ((((-1) * q_l) + ((-1) * q_r)) ^ 2) * (/ ((((-1) * (h ^ 2) * (omega ^ 2)) + 8) ^ 2)) * (omega ^ 2) * m)) * h)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
