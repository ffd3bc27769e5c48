(* Certificate of claim newmark-det: det Phi = 1: the discrete flow is symplectic.
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

Lemma newmark_det_determinant :
  forall h omega : R,
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-4)) <> 0 ->
  ((((((-1) * (h ^ 2) * (omega ^ 2)) + 4) ^ 2) * (/ ((((-1) * (h ^ 2) * (omega ^ 2)) + (-4)) ^ 2))) + (16 * (/ ((((-1) * (h ^ 2) * (omega ^ 2)) + (-4)) ^ 2)) * (h ^ 2) * (omega ^ 2)))
  = 1.
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
