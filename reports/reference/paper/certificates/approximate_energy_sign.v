(* Certificate of claim approximate-energy-sign: Beyond the paper, which never says it: (H_d - H)/(m omega^2 q^2) = omega^4 h^4 / (72 (8 - omega^2 h^2)) is positive when 0 < omega h < 2 sqrt(2), the condition (stabilite), and for no larger omega h: the conserved energy exceeds the true one (q != 0) exactly on the first stable band.
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

Lemma approximate_energy_sign_sign_before :
  forall x : R,
  (((-1) * x) + 8) <> 0 ->
  0 < x ->
  0 < (((-1) * x) + 8) ->
  0 < ((1/72) * (/ (((-1) * x) + 8)) * (x ^ 2)).
Proof.
  intros.
  assert (0 < (/ (((-1) * x) + 8))) by (apply Rinv_0_lt_compat; nra).
  assert (0 < (x ^ 2)) by nra.
  assert (0 < ((/ (((-1) * x) + 8)) * (x ^ 2))) by (apply Rmult_lt_0_compat; assumption).
  nra.
Qed.
