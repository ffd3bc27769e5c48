(* Certificate of claim classical-euler-lagrange: The discrete Euler-Lagrange equation dL_d/dq_r(q_{j-1}, q_j) + dL_d/dq_l(q_j, q_{j+1}) = 0 with (lagrangien-discret) gives m (q_{j+1} - 2 q_j + q_{j-1})/h^2 + 1/2 [V'((q_j + q_{j+1})/2) + V'((q_{j-1} + q_j)/2)] = 0.
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

Lemma classical_euler_lagrange_euler_lagrange :
  forall (dV : R -> R) (h m q_j q_jm1 q_jp1 : R),
  0 < m ->
  0 < h ->
  h <> 0 ->
  ((1/2) * (((-1) * (dV (((1/2) * q_j) + ((1/2) * q_jm1)))) + ((-1) * (dV (((1/2) * q_j) + ((1/2) * q_jp1)))) + (2 * (((-1) * q_jm1) + ((-1) * q_jp1) + (2 * q_j)) * (/ (h ^ 2)) * m)) * h)
  = (((-1) * (((-1) * q_j) + q_jm1) * (/ h) * m) + ((-1) * (((-1) * q_j) + q_jp1) * (/ h) * m) + ((-1/2) * (dV (((1/2) * q_j) + ((1/2) * q_jm1))) * h) + ((-1/2) * (dV (((1/2) * q_j) + ((1/2) * q_jp1))) * h)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
