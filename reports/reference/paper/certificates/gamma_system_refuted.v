(* Refutation of claim gamma-system as printed: Q(Phi y) = Q(y) for all y iff Gamma (xi, eta, zeta)^T = 0 with Gamma = ((alpha^2-1)/2, alpha gamma, gamma^2/2; alpha beta, alpha delta + beta gamma - 1, gamma delta; beta^2/2, beta delta, (gamma^2-1)/2).
   The printed identity, for all values under its hypotheses, is false: each lemma is its negation,
   shown at one point where the two sides differ. Written by simpson-verify from the expressions
   its GiNaC kernel compared; check with coqc. *)
Require Import Reals Field Lra Psatz.
Open Scope R_scope.

(* At the counterexample point every hypothesis is a numeric fact (0 < 3, 24 + 2 ^ 2 * 3 ^ 2 <> 0). *)
Ltac premise := first [ lra | nra ].

Lemma gamma_system_printed_31_refuted :
  ~ (forall beta delta eta gamma xi zeta : R,
  (((-1/2) * (((-1) * (gamma ^ 2)) + 1) * zeta) + ((1/2) * (beta ^ 2) * xi) + (beta * delta * eta))
  = (((-1/2) * (((-1) * (delta ^ 2)) + 1) * zeta) + ((1/2) * (beta ^ 2) * xi) + (beta * delta * eta))).
Proof.
  intro H.
  (* At beta = (2), delta = (3), eta = (5), gamma = (7), xi = (11), zeta = (13) the two sides differ by 260. *)
  assert (D : (((-1/2) * (((-1) * ((7) ^ 2)) + 1) * (13)) + ((1/2) * ((2) ^ 2) * (11)) + ((2) * (3) * (5))) - (((-1/2) * (((-1) * ((3) ^ 2)) + 1) * (13)) + ((1/2) * ((2) ^ 2) * (11)) + ((2) * (3) * (5))) = 260) by (field; premise).
  assert (E : (((-1/2) * (((-1) * ((7) ^ 2)) + 1) * (13)) + ((1/2) * ((2) ^ 2) * (11)) + ((2) * (3) * (5))) = (((-1/2) * (((-1) * ((3) ^ 2)) + 1) * (13)) + ((1/2) * ((2) ^ 2) * (11)) + ((2) * (3) * (5)))) by (apply (H (2) (3) (5) (7) (11) (13)); premise).
  rewrite (Rminus_diag_eq _ _ E) in D.
  lra.
Qed.
