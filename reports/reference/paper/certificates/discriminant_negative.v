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

Lemma discriminant_negative_factor_1 :
  forall x : R,
  0 < x ->
  0 < (((-1) * x) + 8) ->
  0 < ((1/576) * x).
Proof.
  intros.
  assert (0 < x) by nra.
  nra.
Qed.

Lemma discriminant_negative_factor_2 :
  forall x : R,
  0 < x ->
  0 < (((-1) * x) + 8) ->
  ((-12) + x) < 0.
Proof.
  intros.
  assert (0 < (((-1) * x) + 12)) by nra.
  nra.
Qed.

Lemma discriminant_negative_factor_3 :
  forall x : R,
  0 < x ->
  0 < (((-1) * x) + 8) ->
  ((-24) + x) < 0.
Proof.
  intros.
  assert (0 < (((-1) * x) + 24)) by nra.
  nra.
Qed.

Lemma discriminant_negative_factor_4 :
  forall x : R,
  0 < x ->
  0 < (((-1) * x) + 8) ->
  ((-8) + x) < 0.
Proof.
  intros.
  assert (0 < (((-1) * x) + 8)) by nra.
  nra.
Qed.
