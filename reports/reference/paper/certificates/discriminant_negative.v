(* Certificate of claim discriminant-negative: Under the stability condition all the factors of Delta are negative and Delta < 0.
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

Lemma discriminant_negative_delta :
  forall x : R,
  0 < x ->
  0 < (((-1) * x) + 8) ->
  (((-1/144) * ((((-1) * x) + (-24)) ^ 2)) + ((1/576) * ((((-1) * (x ^ 2)) + (-48) + (22 * x)) ^ 2))) < 0.
Proof.
  intros.
  replace (((-1/144) * ((((-1) * x) + (-24)) ^ 2)) + ((1/576) * ((((-1) * (x ^ 2)) + (-48) + (22 * x)) ^ 2)))
    with ((-1/576) * (((-1) * x) + 12) * (((-1) * x) + 24) * (((-1) * x) + 8) * x)
    by (field; repeat split; nonzero).
  assert (0 < (((-1) * x) + 12)) by nra.
  assert (0 < (((-1) * x) + 24)) by nra.
  assert (0 < ((((-1) * x) + 12) * (((-1) * x) + 24))) by (apply Rmult_lt_0_compat; assumption).
  assert (0 < (((-1) * x) + 8)) by nra.
  assert (0 < (((((-1) * x) + 12) * (((-1) * x) + 24)) * (((-1) * x) + 8))) by (apply Rmult_lt_0_compat; assumption).
  assert (0 < x) by nra.
  assert (0 < ((((((-1) * x) + 12) * (((-1) * x) + 24)) * (((-1) * x) + 8)) * x)) by (apply Rmult_lt_0_compat; assumption).
  nra.
Qed.

Lemma discriminant_negative_factor_24 :
  forall x : R,
  0 < x ->
  0 < (((-1) * x) + 8) ->
  ((-24) + x) < 0.
Proof.
  intros.
  assert (0 < (((-1) * x) + 24)) by nra.
  nra.
Qed.

Lemma discriminant_negative_factor_12 :
  forall x : R,
  0 < x ->
  0 < (((-1) * x) + 8) ->
  ((-12) + x) < 0.
Proof.
  intros.
  assert (0 < (((-1) * x) + 12)) by nra.
  nra.
Qed.

Lemma discriminant_negative_factor_8 :
  forall x : R,
  0 < x ->
  0 < (((-1) * x) + 8) ->
  ((-8) + x) < 0.
Proof.
  intros.
  assert (0 < (((-1) * x) + 8)) by nra.
  nra.
Qed.
