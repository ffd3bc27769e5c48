(* Certificate of claim qm-not-affine: This interpolation is not linear if h > 0.
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

Lemma qm_not_affine_linear :
  forall h omega q_l q_r : R,
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + 8) <> 0 ->
  ((-4) * (((-1) * q_l) + ((-1) * q_r)) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 8)))
  = ((4 * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 8)) * q_l) + (4 * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 8)) * q_r)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
