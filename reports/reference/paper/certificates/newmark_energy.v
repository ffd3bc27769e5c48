(* Certificate of claim newmark-energy: H_j = p_j^2/(2m) + m omega^2 q_j^2/2 is conserved: H_{j+1} = H_j.
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

Lemma newmark_energy_conserved :
  forall h m omega p_j q_j : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-4)) <> 0 ->
  m <> 0 ->
  (((1/2) * ((((((-1) * (h ^ 2) * (omega ^ 2)) + 4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * p_j) + ((-4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * (omega ^ 2) * h * m * q_j)) ^ 2) * (/ m)) + ((1/2) * ((((((-1) * (h ^ 2) * (omega ^ 2)) + 4) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * q_j) + (4 * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-4))) * (/ m) * h * p_j)) ^ 2) * (omega ^ 2) * m))
  = (((1/2) * (/ m) * (p_j ^ 2)) + ((1/2) * (omega ^ 2) * (q_j ^ 2) * m)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
