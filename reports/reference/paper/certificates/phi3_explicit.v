(* Certificate of claim phi3-explicit: The symplectic Simpson scheme defined by Phi_3 is an explicit scheme.
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

Lemma phi3_explicit_denominator_1 :
  forall h m omega : R,
  0 < m ->
  0 < h ->
  0 < h ->
  0 < m ->
  0 < omega ->
  0 < (((h ^ 2) * (omega ^ 2)) + 24).
Proof.
  intros.
  assert (0 <= (h * omega) ^ 2) by apply pow2_ge_0.
  assert (0 < (((h ^ 2) * (omega ^ 2)) + 24)) by nra.
  nra.
Qed.
