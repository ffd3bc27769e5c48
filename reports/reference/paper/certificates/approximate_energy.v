(* Certificate of claim approximate-energy: The abstract: "satisfying the conservation of an approximate energy". The conserved H_d (hamiltonien-discret) is the energy H = p^2/(2m) + m omega^2 q^2/2 plus m omega^6 h^4 q^2 / (72 (8 - omega^2 h^2)): it approximates H to order h^4.
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

Lemma approximate_energy_identity :
  forall h m omega p q : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + 8) <> 0 ->
  m <> 0 ->
  (((1/2) * (/ m) * (p ^ 2)) + ((1/72) * (((-1) * (h ^ 2) * (omega ^ 2)) + 12) * (((-1) * (h ^ 2) * (omega ^ 2)) + 24) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 8)) * (omega ^ 2) * (q ^ 2) * m))
  = (((1/2) * (/ m) * (p ^ 2)) + ((1/2) * (omega ^ 2) * (q ^ 2) * m) + ((1/72) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 8)) * (h ^ 4) * (omega ^ 6) * (q ^ 2) * m)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
