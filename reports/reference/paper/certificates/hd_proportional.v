(* Certificate of claim hd-proportional: H_d = p^2/(2m) + m omega^2 (1 - omega^2 h^2/12)(1 - omega^2 h^2/24) q^2/(2 (1 - omega^2 h^2/8)) is the conserved form Q_c of Phi_3 up to a constant.
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

Lemma hd_proportional_proportional :
  forall h m omega p q : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) <> 0 ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + 8) <> 0 ->
  h <> 0 ->
  m <> 0 ->
  (((1/2) * (/ m) * (p ^ 2)) + ((1/72) * (((-1) * (h ^ 2) * (omega ^ 2)) + 12) * (((-1) * (h ^ 2) * (omega ^ 2)) + 24) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 8)) * (omega ^ 2) * (q ^ 2) * m))
  = ((1/72) * (((((-1) * (h ^ 2) * (omega ^ 2)) + 12) * (((-1) * (h ^ 2) * (omega ^ 2)) + 24) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24))) * (omega ^ 2) * (q ^ 2) * h * m) + (36 * (((-1) * (h ^ 2) * (omega ^ 2)) + 8) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + (-24))) * (/ m) * (p ^ 2) * h)) * (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 8)) * (/ h)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
