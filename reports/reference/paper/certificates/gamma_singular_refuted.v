(* Refutation of claim gamma-singular as printed: Read as the derivation needs it: the printed system Gamma is singular when alpha delta - beta gamma = 1. (The sentence says that "this expression", the printed product, vanishes there: literally true, its first factor being alpha delta - beta gamma - 1; what the derivation uses is that Gamma itself is singular, a consequence of gamma-system.)
   The printed identity, for all values under its hypotheses, is false: each lemma is its negation,
   shown at one point where the two sides differ. Written by simpson-verify from the expressions
   its GiNaC kernel compared; check with coqc. *)
Require Import Reals Field Lra Psatz.
Open Scope R_scope.

(* At the counterexample point every hypothesis is a numeric fact (0 < 3, 24 + 2 ^ 2 * 3 ^ 2 <> 0). *)
Ltac premise := first [ lra | nra ].

Lemma gamma_singular_printed_refuted :
  ~ (forall alpha beta gamma : R,
  alpha <> 0 ->
  (((-1/2) * (((((-1) * beta * gamma) + (-1)) * (beta ^ 2)) + ((beta ^ 3) * gamma)) * (gamma ^ 2)) + ((1/2) * ((((((-1) * beta * gamma) + (-1)) ^ 2) * (/ (alpha ^ 2)) * beta * gamma) + ((((-1) * (gamma ^ 2)) + 1) * beta * gamma)) * (((-1) * (alpha ^ 2)) + 1)) + ((1/2) * (((((-1) * (gamma ^ 2)) + 1) * alpha * beta) + ((-1) * (((-1) * beta * gamma) + (-1)) * (/ alpha) * (beta ^ 2) * gamma)) * alpha * gamma))
  = 0).
Proof.
  intro H.
  (* At alpha = (2), beta = (3), gamma = (5) the two sides differ by (585/2). *)
  assert (D : (((-1/2) * (((((-1) * (3) * (5)) + (-1)) * ((3) ^ 2)) + (((3) ^ 3) * (5))) * ((5) ^ 2)) + ((1/2) * ((((((-1) * (3) * (5)) + (-1)) ^ 2) * (/ ((2) ^ 2)) * (3) * (5)) + ((((-1) * ((5) ^ 2)) + 1) * (3) * (5))) * (((-1) * ((2) ^ 2)) + 1)) + ((1/2) * (((((-1) * ((5) ^ 2)) + 1) * (2) * (3)) + ((-1) * (((-1) * (3) * (5)) + (-1)) * (/ (2)) * ((3) ^ 2) * (5))) * (2) * (5))) - 0 = (585/2)) by (field; premise).
  assert (E : (((-1/2) * (((((-1) * (3) * (5)) + (-1)) * ((3) ^ 2)) + (((3) ^ 3) * (5))) * ((5) ^ 2)) + ((1/2) * ((((((-1) * (3) * (5)) + (-1)) ^ 2) * (/ ((2) ^ 2)) * (3) * (5)) + ((((-1) * ((5) ^ 2)) + 1) * (3) * (5))) * (((-1) * ((2) ^ 2)) + 1)) + ((1/2) * (((((-1) * ((5) ^ 2)) + 1) * (2) * (3)) + ((-1) * (((-1) * (3) * (5)) + (-1)) * (/ (2)) * ((3) ^ 2) * (5))) * (2) * (5))) = 0) by (apply (H (2) (3) (5)); premise).
  rewrite (Rminus_diag_eq _ _ E) in D.
  lra.
Qed.
