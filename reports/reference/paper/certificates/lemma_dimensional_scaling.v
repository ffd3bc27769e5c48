(* Certificate of claim lemma-dimensional-scaling: (Not a claim of the paper; the reduction every exact proof uses.) With S = diag(m omega, 1), Phi_3(m, omega, h) = S Phi_3(1, 1, omega h) S^-1 and likewise for Phi; H_d and H scale by m omega^2 with p/(m omega); (schema-ordre-3) scales by omega^2; q_m is invariant, and p_r, L_h^r, L_h, L_d and its momentum scale by m omega (so the elimination route of Section 6, built from p_r and the scheme, transforms like Phi_3).
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
(* Not stated: lemma_dimensional_scaling_phi3_11, lemma_dimensional_scaling_phi3_12, lemma_dimensional_scaling_phi3_21, lemma_dimensional_scaling_phi3_22, lemma_dimensional_scaling_newmark_11, lemma_dimensional_scaling_newmark_12, lemma_dimensional_scaling_newmark_21, lemma_dimensional_scaling_newmark_22, whose two sides GiNaC evaluates to one expression (X = X checks nothing). *)

Lemma lemma_dimensional_scaling_discrete_energy :
  forall h m omega p q : R,
  0 < m ->
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + 8) <> 0 ->
  m <> 0 ->
  omega <> 0 ->
  (((1/2) * (/ m) * (p ^ 2)) + ((1/72) * (((-1) * (h ^ 2) * (omega ^ 2)) + 12) * (((-1) * (h ^ 2) * (omega ^ 2)) + 24) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 8)) * (omega ^ 2) * (q ^ 2) * m))
  = ((1/72) * (((((-1) * (h ^ 2) * (omega ^ 2)) + 12) * (((-1) * (h ^ 2) * (omega ^ 2)) + 24) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 8)) * (q ^ 2)) + (36 * (/ (m ^ 2)) * (/ (omega ^ 2)) * (p ^ 2))) * (omega ^ 2) * m).
Proof.
  intros.
  field; repeat split; nonzero.
Qed.
