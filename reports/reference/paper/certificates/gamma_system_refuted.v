(* Refutation of claim gamma-system as printed: Q(Phi y) = Q(y) for all y iff Gamma (xi, eta, zeta)^T = 0 with Gamma = ((alpha^2-1)/2, alpha gamma, gamma^2/2; alpha beta, alpha delta + beta gamma - 1, gamma delta; beta^2/2, beta delta, (gamma^2-1)/2).
   The printed identity, for all values under its hypotheses, is false: each lemma is its negation,
   shown at one point where the two sides differ. Written by simpson-verify from the expressions
   its GiNaC kernel compared; check with coqc. *)
Require Import Reals Field Lra Psatz.
Open Scope R_scope.

(* At the counterexample point every hypothesis is a numeric fact (0 < 3, 24 + 2 ^ 2 * 3 ^ 2 <> 0). *)
Ltac premise := first [ lra | nra ].

Lemma gamma_system_system_refuted :
  ~ (forall alpha beta delta eta gamma p q xi zeta : R,
  (((((-1) * alpha * p) + ((-1) * beta * q)) * (((-1) * delta * q) + ((-1) * gamma * p)) * eta) + ((-1) * eta * p * q) + ((-1/2) * (p ^ 2) * xi) + ((-1/2) * (q ^ 2) * zeta) + ((1/2) * ((((-1) * alpha * p) + ((-1) * beta * q)) ^ 2) * xi) + ((1/2) * ((((-1) * delta * q) + ((-1) * gamma * p)) ^ 2) * zeta))
  = (((-1) * (((((-1) * alpha * delta) + ((-1) * beta * gamma) + 1) * eta) + ((-1) * alpha * beta * xi) + ((-1) * delta * gamma * zeta)) * p * q) + ((-1/2) * (((((-1) * (alpha ^ 2)) + 1) * xi) + ((-1) * (gamma ^ 2) * zeta) + ((-2) * alpha * eta * gamma)) * (p ^ 2)) + ((-1/2) * (((((-1) * (gamma ^ 2)) + 1) * zeta) + ((-1) * (beta ^ 2) * xi) + ((-2) * beta * delta * eta)) * (q ^ 2)))).
Proof.
  intro H.
  (* At alpha = (2), beta = (3), delta = (5), eta = (7), gamma = (11), p = (13), q = (17), xi = (19), zeta = (23) the two sides differ by (-319056). *)
  assert (D : (((((-1) * (2) * (13)) + ((-1) * (3) * (17))) * (((-1) * (5) * (17)) + ((-1) * (11) * (13))) * (7)) + ((-1) * (7) * (13) * (17)) + ((-1/2) * ((13) ^ 2) * (19)) + ((-1/2) * ((17) ^ 2) * (23)) + ((1/2) * ((((-1) * (2) * (13)) + ((-1) * (3) * (17))) ^ 2) * (19)) + ((1/2) * ((((-1) * (5) * (17)) + ((-1) * (11) * (13))) ^ 2) * (23))) - (((-1) * (((((-1) * (2) * (5)) + ((-1) * (3) * (11)) + 1) * (7)) + ((-1) * (2) * (3) * (19)) + ((-1) * (5) * (11) * (23))) * (13) * (17)) + ((-1/2) * (((((-1) * ((2) ^ 2)) + 1) * (19)) + ((-1) * ((11) ^ 2) * (23)) + ((-2) * (2) * (7) * (11))) * ((13) ^ 2)) + ((-1/2) * (((((-1) * ((11) ^ 2)) + 1) * (23)) + ((-1) * ((3) ^ 2) * (19)) + ((-2) * (3) * (5) * (7))) * ((17) ^ 2))) = (-319056)) by (field; premise).
  assert (E : (((((-1) * (2) * (13)) + ((-1) * (3) * (17))) * (((-1) * (5) * (17)) + ((-1) * (11) * (13))) * (7)) + ((-1) * (7) * (13) * (17)) + ((-1/2) * ((13) ^ 2) * (19)) + ((-1/2) * ((17) ^ 2) * (23)) + ((1/2) * ((((-1) * (2) * (13)) + ((-1) * (3) * (17))) ^ 2) * (19)) + ((1/2) * ((((-1) * (5) * (17)) + ((-1) * (11) * (13))) ^ 2) * (23))) = (((-1) * (((((-1) * (2) * (5)) + ((-1) * (3) * (11)) + 1) * (7)) + ((-1) * (2) * (3) * (19)) + ((-1) * (5) * (11) * (23))) * (13) * (17)) + ((-1/2) * (((((-1) * ((2) ^ 2)) + 1) * (19)) + ((-1) * ((11) ^ 2) * (23)) + ((-2) * (2) * (7) * (11))) * ((13) ^ 2)) + ((-1/2) * (((((-1) * ((11) ^ 2)) + 1) * (23)) + ((-1) * ((3) ^ 2) * (19)) + ((-2) * (3) * (5) * (7))) * ((17) ^ 2)))) by (apply (H (2) (3) (5) (7) (11) (13) (17) (19) (23)); premise).
  rewrite (Rminus_diag_eq _ _ E) in D.
  lra.
Qed.
