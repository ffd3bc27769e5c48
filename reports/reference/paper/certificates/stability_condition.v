(* Certificate of claim stability-condition: The condition (stabilite) 0 < omega h < 2 sqrt(2) is a stability condition of the scheme (schema-ordre-3): the scheme is stable for every omega h in it (whether it emerges from q_m, stability-emerges judges).
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
(* Not stated: stability_condition_reversible, whose two sides GiNaC evaluates to one expression (X = X checks nothing). *)

Lemma stability_condition_stable_band :
  forall x : R,
  (((-1) * (x ^ 2)) + ((-48) * x) + (-576)) <> 0 ->
  (((-1) * x) + (-24)) <> 0 ->
  0 < x ->
  0 < (((-1) * x) + 8) ->
  ((((-1) * (x ^ 4)) + ((-576) * (x ^ 2)) + (2304 * x) + (44 * (x ^ 3))) * (/ (((-1) * (x ^ 2)) + ((-48) * x) + (-576)))) < 0.
Proof.
  intros.
  replace ((((-1) * (x ^ 4)) + ((-576) * (x ^ 2)) + (2304 * x) + (44 * (x ^ 3))) * (/ (((-1) * (x ^ 2)) + ((-48) * x) + (-576))))
    with ((-1) * (((-1) * x) + 12) * (((-1) * x) + 24) * (((-1) * x) + 8) * (/ ((((-1) * x) + (-24)) ^ 2)) * x)
    by (field; repeat split; nonzero).
  assert (0 < (((-1) * x) + 12)) by nra.
  assert (0 < (((-1) * x) + 24)) by nra.
  assert (0 < ((((-1) * x) + 12) * (((-1) * x) + 24))) by (apply Rmult_lt_0_compat; assumption).
  assert (0 < (((-1) * x) + 8)) by nra.
  assert (0 < (((((-1) * x) + 12) * (((-1) * x) + 24)) * (((-1) * x) + 8))) by (apply Rmult_lt_0_compat; assumption).
  assert (0 < (/ ((((-1) * x) + (-24)) ^ 2))) by (apply Rinv_0_lt_compat; nra).
  assert (0 < ((((((-1) * x) + 12) * (((-1) * x) + 24)) * (((-1) * x) + 8)) * (/ ((((-1) * x) + (-24)) ^ 2)))) by (apply Rmult_lt_0_compat; assumption).
  assert (0 < x) by nra.
  assert (0 < (((((((-1) * x) + 12) * (((-1) * x) + 24)) * (((-1) * x) + 8)) * (/ ((((-1) * x) + (-24)) ^ 2))) * x)) by (apply Rmult_lt_0_compat; assumption).
  nra.
Qed.
