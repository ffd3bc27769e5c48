(* Certificate of claim qm-harmonic: For the harmonic oscillator, q_m = (q_l + q_r)/(2 (1 - omega^2 h^2/8)).
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

Lemma qm_harmonic_solution :
  forall h m omega q_l q_r : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + 8) <> 0 ->
  h <> 0 ->
  (((-4) * (((-1) * q_l) + ((-1) * q_r) + ((-8) * (((-1) * q_l) + ((-1) * q_r)) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 8)))) * (/ (h ^ 2)) * m) + ((-4) * (((-1) * q_l) + ((-1) * q_r)) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 8)) * (omega ^ 2) * m))
  = 0.
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
