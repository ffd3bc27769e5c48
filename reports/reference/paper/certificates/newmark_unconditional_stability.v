(* Certificate of claim newmark-unconditional-stability: For V = m omega^2 q^2/2 the scheme (schema-ordre-deux) is linearly stable; it is an unconditionally stable version of the Newmark scheme.
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

Lemma newmark_unconditional_stability_discriminant :
  forall h omega : R,
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-4)) <> 0 ->
  0 < h ->
  0 < omega ->
  ((-64) * (/ ((((-1) * (h ^ 2) * (omega ^ 2)) + (-4)) ^ 2)) * (h ^ 2) * (omega ^ 2)) < 0.
Proof.
  intros.
  assert (0 < (/ ((((-1) * (h ^ 2) * (omega ^ 2)) + (-4)) ^ 2))) by (apply Rinv_0_lt_compat; nra).
  assert (0 < (h ^ 2)) by nra.
  assert (0 < ((/ ((((-1) * (h ^ 2) * (omega ^ 2)) + (-4)) ^ 2)) * (h ^ 2))) by (apply Rmult_lt_0_compat; assumption).
  assert (0 < (omega ^ 2)) by nra.
  assert (0 < (((/ ((((-1) * (h ^ 2) * (omega ^ 2)) + (-4)) ^ 2)) * (h ^ 2)) * (omega ^ 2))) by (apply Rmult_lt_0_compat; assumption).
  nra.
Qed.
