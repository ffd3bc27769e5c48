(* Certificate of claim interpolant-nodal: q(0) = q_l, q(h/2) = q_m and q(h) = q_r.
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

Lemma interpolant_nodal_core :
  forall q_l q_m q_r theta : R,
  (((((-1) * theta) + 1) * (((-2) * theta) + 1) * q_l) + ((-1) * (((-2) * theta) + 1) * q_r * theta) + (4 * (((-1) * theta) + 1) * q_m * theta))
  = (((-1) * q_r * theta) + ((-3) * q_l * theta) + ((-4) * (theta ^ 2) * q_m) + (2 * (theta ^ 2) * q_l) + (2 * (theta ^ 2) * q_r) + (4 * q_m * theta) + q_l).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
