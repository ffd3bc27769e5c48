(* Certificate of claim phi3-shear-factorization: (Not in the paper.) Phi_3 = L(c) U(b) L(c) with L(c) = ((1, 0), (c, 1)), U(b) = ((1, b), (0, 1)), b = beta, c = h/(2m(1 - omega^2 h^2/12)), for every h except omega^2 h^2 = 12 (at 24, b = beta = 0 and Phi_3 = L(2c)); at 12 no such product exists.
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
(* Not stated: phi3_shear_factorization_core_12, whose two sides GiNaC evaluates to one expression (X = X checks nothing). *)

Lemma phi3_shear_factorization_core_11 :
  forall h omega : R,
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) <> 0 ->
  (((1/2) * (((-1) * (h ^ 2) * (omega ^ 2)) + 24) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24))) * (h ^ 2) * (omega ^ 2)) + 1)
  = ((1/2) * (((-1) * (h ^ 4) * (omega ^ 4)) + (-48) + (22 * (h ^ 2) * (omega ^ 2))) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)))).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma phi3_shear_factorization_core_21 :
  forall h m omega : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) <> 0 ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + 12) <> 0 ->
  m <> 0 ->
  ((3 * (((((-1) * (h ^ 2) * (omega ^ 2)) + 24) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24))) * (h ^ 2) * (omega ^ 2)) + 2) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 12)) * (/ m) * h) + (6 * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 12)) * (/ m) * h))
  = ((-3) * (((-1) * (h ^ 2) * (omega ^ 2)) + 8) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24))) * (/ m) * h).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma phi3_shear_factorization_core_22 :
  forall h omega : R,
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) <> 0 ->
  (((1/2) * (((-1) * (h ^ 2) * (omega ^ 2)) + 24) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24))) * (h ^ 2) * (omega ^ 2)) + 1)
  = ((1/2) * (((-1) * (h ^ 4) * (omega ^ 4)) + (-48) + (22 * (h ^ 2) * (omega ^ 2))) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)))).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
