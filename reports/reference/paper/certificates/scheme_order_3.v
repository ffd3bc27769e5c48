(* Certificate of claim scheme-order-3: The discrete Euler-Lagrange equation of L_h^r is (q_{j+1} - 2 q_j + q_{j-1})/h^2 + (omega^2/24)(q_{j+1} + 22 q_j + q_{j-1}) - (omega^4 h^2/24) q_j = 0.
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

Lemma scheme_order_3_euler_lagrange :
  forall h m omega q_j q_jm1 q_jp1 : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + 8) <> 0 ->
  h <> 0 ->
  ((1/3) * (((((-1) * q_jm1) + ((-1) * q_jp1) + ((-22) * q_j)) * (omega ^ 2)) + ((h ^ 2) * (omega ^ 4) * q_j) + (24 * (((-1) * q_jm1) + ((-1) * q_jp1) + (2 * q_j)) * (/ (h ^ 2)))) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 8)) * h * m)
  = (((-1/6) * (((((((-1) * (h ^ 2) * (omega ^ 2)) + 22) * q_j) + (2 * q_jm1)) * (omega ^ 2) * h * m) + (48 * (((-1) * q_j) + q_jm1) * (/ h) * m)) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 8))) + ((-1/6) * (((((((-1) * (h ^ 2) * (omega ^ 2)) + 22) * q_j) + (2 * q_jp1)) * (omega ^ 2) * h * m) + (48 * (((-1) * q_j) + q_jp1) * (/ h) * m)) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 8)))).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
