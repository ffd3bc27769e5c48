(* Certificate of claim gamma-system: Q(Phi y) = Q(y) for all y iff Gamma (xi, eta, zeta)^T = 0 with Gamma = ((alpha^2-1)/2, alpha gamma, gamma^2/2; alpha beta, alpha delta + beta gamma - 1, gamma delta; beta^2/2, beta delta, (gamma^2-1)/2).
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
(* Not stated here (GiNaC refuted them): printed. *)

Lemma gamma_system_core_11 :
  forall alpha eta gamma xi zeta : R,
  (((-1/2) * (((-1) * (alpha ^ 2)) + 1) * xi) + ((1/2) * (gamma ^ 2) * zeta) + (alpha * eta * gamma))
  = (((-1/2) * (((-1) * (alpha ^ 2)) + 1) * xi) + ((1/2) * (gamma ^ 2) * zeta) + (alpha * eta * gamma)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma gamma_system_core_21 :
  forall alpha beta delta eta gamma xi zeta : R,
  (((-1) * (((-1) * alpha * delta) + ((-1) * beta * gamma) + 1) * eta) + (alpha * beta * xi) + (delta * gamma * zeta))
  = (((-1) * (((-1) * alpha * delta) + ((-1) * beta * gamma) + 1) * eta) + (alpha * beta * xi) + (delta * gamma * zeta)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.

Lemma gamma_system_core_31 :
  forall beta delta eta xi zeta : R,
  (((-1/2) * (((-1) * (delta ^ 2)) + 1) * zeta) + ((1/2) * (beta ^ 2) * xi) + (beta * delta * eta))
  = (((-1/2) * (((-1) * (delta ^ 2)) + 1) * zeta) + ((1/2) * (beta ^ 2) * xi) + (beta * delta * eta)).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
