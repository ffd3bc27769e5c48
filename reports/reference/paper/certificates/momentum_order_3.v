(* Certificate of claim momentum-order-3: p_r = dL_h^r/dq_r = m (q_r - q_l)/h - h (m omega^2/6)(q_l + 2 q_r)/(1 - omega^2 h^2/8) + h^3 (m omega^4/48) q_r/(1 - omega^2 h^2/8).
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

Lemma momentum_order_3_derivative :
  forall h m omega q_l q_r : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + 8) <> 0 ->
  h <> 0 ->
  ((-1/6) * (((((((-1) * (h ^ 2) * (omega ^ 2)) + 22) * q_r) + (2 * q_l)) * (omega ^ 2) * h * m) + ((-48) * (((-1) * q_l) + q_r) * (/ h) * m)) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 8)))
  = (((((-1) * q_l) + q_r) * (/ h) * m) + ((1/6) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 8)) * (h ^ 3) * (omega ^ 4) * m * q_r) + ((4/3) * (((-1) * q_l) + ((-2) * q_r)) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 8)) * (omega ^ 2) * h * m)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
