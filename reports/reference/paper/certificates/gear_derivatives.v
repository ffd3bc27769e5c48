(* Certificate of claim gear-derivatives: g_l = dq/dt(0) = (-3 q_l + 4 q_m - q_r)/h, g_r = dq/dt(h) = (q_l - 4 q_m + 3 q_r)/h.
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
(* Not stated: gear_derivatives_printed, gear_derivatives_core, gear_derivatives_printed_2, gear_derivatives_core_2, gear_derivatives_printed_exact, gear_derivatives_core_exact, whose two sides GiNaC evaluates to one expression (X = X checks nothing). *)

Lemma gear_derivatives_printed_exact_2 :
  forall c1 c2 h : R,
  0 < h ->
  h <> 0 ->
  ((-1) * (((-1) * c1 * h) + ((-2) * (h ^ 2) * c2)) * (/ h))
  = ((2 * c2 * h) + c1).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma gear_derivatives_core_exact_2 :
  forall c1 c2 h : R,
  0 < h ->
  h <> 0 ->
  ((-1) * (((-1) * c1 * h) + ((-2) * (h ^ 2) * c2)) * (/ h))
  = ((2 * c2 * h) + c1).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
