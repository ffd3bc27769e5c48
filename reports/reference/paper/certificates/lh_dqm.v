(* Certificate of claim lh-dqm: dL_h/dq_m = (h/12) [(8m/h) g_l - (8m/h) g_r - 8 dV/dq(q_m)].
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

Lemma lh_dqm_derivative :
  forall (dV : R -> R) (h m q_l q_m q_r : R),
  0 < m ->
  0 < h ->
  h <> 0 ->
  (((-2/3) * (dV q_m) * h) + ((2/3) * (((((-1) * q_l) + ((-3) * q_r) + (4 * q_m)) * (/ (h ^ 2))) + ((((-1) * q_r) + ((-3) * q_l) + (4 * q_m)) * (/ (h ^ 2)))) * h * m))
  = ((2/3) * (((((-1) * q_l) + ((-3) * q_r) + (4 * q_m)) * (/ (h ^ 2)) * m) + ((((-1) * q_r) + ((-3) * q_l) + (4 * q_m)) * (/ (h ^ 2)) * m) + ((-1) * (dV q_m))) * h).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
