(* Certificate of claim characteristic-equation: With q_{j-1} = 1, q_j = r, q_{j+1} = r^2: a r^2 + b r + c = 0 with a = 1 + h^2 omega^2/24 and b = -(48 - 22 h^2 omega^2 + h^4 omega^4)/24.
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

Lemma characteristic_equation_characteristic :
  forall h omega r : R,
  0 < h ->
  h <> 0 ->
  ((1/576) * (((((-1) * (r ^ 2)) + ((-22) * r) + (-1)) * (omega ^ 2)) + ((h ^ 2) * (omega ^ 4) * r) + (24 * (((-1) * (r ^ 2)) + (-1) + (2 * r)) * (/ (h ^ 2)))) * (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)))
  = ((1/576) * (((((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) * (r ^ 2)) + ((-1) * (((-1) * (h ^ 4) * (omega ^ 4)) + (-48) + (22 * (h ^ 2) * (omega ^ 2))) * r) + ((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) * (((-1) * (h ^ 2) * (omega ^ 2)) + (-24)) * (/ (h ^ 2))).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
