(* Certificate of claim discriminant-factorization: Delta = b^2 - 4ac = (omega^2 h^2/576)(omega^2 h^2 - 24)(omega^2 h^2 - 12)(omega^2 h^2 - 8).
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

Lemma discriminant_factorization_discriminant :
  forall h omega : R,
  0 < h ->
  (((-1/144) * ((((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) ^ 2)) + ((1/576) * ((((-1) * (h ^ 4) * (omega ^ 4)) + (-48) + (22 * (h ^ 2) * (omega ^ 2))) ^ 2)))
  = ((-1/576) * (((-1) * (h ^ 2) * (omega ^ 2)) + 12) * (((-1) * (h ^ 2) * (omega ^ 2)) + 24) * (((-1) * (h ^ 2) * (omega ^ 2)) + 8) * (h ^ 2) * (omega ^ 2)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
