(* Refutation of claim gamma-determinant as printed: det Gamma = (alpha delta - beta gamma - 1)(1 - alpha - delta + alpha delta - beta gamma)(1 + alpha + delta + alpha delta - beta gamma).
   The printed identity, for all values under its hypotheses, is false: each lemma is its negation,
   shown at one point where the two sides differ. Written by simpson-verify from the expressions
   its GiNaC kernel compared; check with coqc. *)
Require Import Reals Field Lra Psatz.
Open Scope R_scope.

(* At the counterexample point every hypothesis is a numeric fact (0 < 3, 24 + 2 ^ 2 * 3 ^ 2 <> 0). *)
Ltac premise := first [ lra | nra ].

Lemma gamma_determinant_determinant_refuted :
  ~ (forall alpha beta delta gamma : R,
  (((-1/4) * (alpha ^ 2) * (delta ^ 2)) + ((-1/4) * (alpha ^ 3) * delta) + ((-1/4) * (beta ^ 3) * (gamma ^ 3)) + ((-1/4) * (delta ^ 3) * alpha) + ((-3/4) * (alpha ^ 2) * (delta ^ 2) * beta * gamma) + ((1/4) * (alpha ^ 2) * beta * gamma) + ((1/4) * (alpha ^ 2)) + ((1/4) * (alpha ^ 3) * (delta ^ 3)) + ((1/4) * (beta ^ 2) * (gamma ^ 2)) + ((1/4) * (delta ^ 2) * beta * gamma) + ((1/4) * (delta ^ 2)) + ((1/4) * alpha * delta) + ((1/4) * beta * gamma) + ((3/4) * (beta ^ 2) * (gamma ^ 2) * alpha * delta) + (-1/4))
  = ((-1) * (((-1) * alpha * delta) + ((-1) * alpha) + ((-1) * delta) + (-1) + (beta * gamma)) * (((-1) * alpha * delta) + (-1) + (beta * gamma) + alpha + delta) * (((-1) * alpha * delta) + (beta * gamma) + 1))).
Proof.
  intro H.
  (* At alpha = (2), beta = (3), delta = (5), gamma = (7) the two sides differ by 459. *)
  assert (D : (((-1/4) * ((2) ^ 2) * ((5) ^ 2)) + ((-1/4) * ((2) ^ 3) * (5)) + ((-1/4) * ((3) ^ 3) * ((7) ^ 3)) + ((-1/4) * ((5) ^ 3) * (2)) + ((-3/4) * ((2) ^ 2) * ((5) ^ 2) * (3) * (7)) + ((1/4) * ((2) ^ 2) * (3) * (7)) + ((1/4) * ((2) ^ 2)) + ((1/4) * ((2) ^ 3) * ((5) ^ 3)) + ((1/4) * ((3) ^ 2) * ((7) ^ 2)) + ((1/4) * ((5) ^ 2) * (3) * (7)) + ((1/4) * ((5) ^ 2)) + ((1/4) * (2) * (5)) + ((1/4) * (3) * (7)) + ((3/4) * ((3) ^ 2) * ((7) ^ 2) * (2) * (5)) + (-1/4)) - ((-1) * (((-1) * (2) * (5)) + ((-1) * (2)) + ((-1) * (5)) + (-1) + ((3) * (7))) * (((-1) * (2) * (5)) + (-1) + ((3) * (7)) + (2) + (5)) * (((-1) * (2) * (5)) + ((3) * (7)) + 1)) = 459) by (field; premise).
  assert (E : (((-1/4) * ((2) ^ 2) * ((5) ^ 2)) + ((-1/4) * ((2) ^ 3) * (5)) + ((-1/4) * ((3) ^ 3) * ((7) ^ 3)) + ((-1/4) * ((5) ^ 3) * (2)) + ((-3/4) * ((2) ^ 2) * ((5) ^ 2) * (3) * (7)) + ((1/4) * ((2) ^ 2) * (3) * (7)) + ((1/4) * ((2) ^ 2)) + ((1/4) * ((2) ^ 3) * ((5) ^ 3)) + ((1/4) * ((3) ^ 2) * ((7) ^ 2)) + ((1/4) * ((5) ^ 2) * (3) * (7)) + ((1/4) * ((5) ^ 2)) + ((1/4) * (2) * (5)) + ((1/4) * (3) * (7)) + ((3/4) * ((3) ^ 2) * ((7) ^ 2) * (2) * (5)) + (-1/4)) = ((-1) * (((-1) * (2) * (5)) + ((-1) * (2)) + ((-1) * (5)) + (-1) + ((3) * (7))) * (((-1) * (2) * (5)) + (-1) + ((3) * (7)) + (2) + (5)) * (((-1) * (2) * (5)) + ((3) * (7)) + 1))) by (apply (H (2) (3) (5) (7)); premise).
  rewrite (Rminus_diag_eq _ _ E) in D.
  lra.
Qed.
