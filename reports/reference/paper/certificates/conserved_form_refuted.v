(* Refutation of claim conserved-form as printed: When alpha = delta, eta = 0 and Q_c(p, q) = gamma p^2/2 - beta q^2/2 is conserved, up to a multiplicative constant.
   The printed identity, for all values under its hypotheses, is false: each lemma is its negation,
   shown at one point where the two sides differ. Written by simpson-verify from the expressions
   its GiNaC kernel compared; check with coqc. *)
Require Import Reals Field Lra Psatz.
Open Scope R_scope.

(* At the counterexample point every hypothesis is a numeric fact (0 < 3, 24 + 2 ^ 2 * 3 ^ 2 <> 0). *)
Ltac premise := first [ lra | nra ].

Lemma conserved_form_kernel_refuted :
  ~ (forall alpha beta q : R,
  beta <> 0 ->
  (((-1/2) * ((((((-1) * (alpha ^ 2)) + 1) ^ 2) * (/ (beta ^ 2))) + (-1)) * (q ^ 2) * beta) + ((-1/2) * (((-1) * (alpha ^ 2)) + 1) * (q ^ 2) * beta))
  = 0).
Proof.
  intro H.
  (* At alpha = (2), beta = (3), q = (5) the two sides differ by (225/2). *)
  assert (D : (((-1/2) * ((((((-1) * ((2) ^ 2)) + 1) ^ 2) * (/ ((3) ^ 2))) + (-1)) * ((5) ^ 2) * (3)) + ((-1/2) * (((-1) * ((2) ^ 2)) + 1) * ((5) ^ 2) * (3))) - 0 = (225/2)) by (field; premise).
  assert (E : (((-1/2) * ((((((-1) * ((2) ^ 2)) + 1) ^ 2) * (/ ((3) ^ 2))) + (-1)) * ((5) ^ 2) * (3)) + ((-1/2) * (((-1) * ((2) ^ 2)) + 1) * ((5) ^ 2) * (3))) = 0) by (apply (H (2) (3) (5)); premise).
  rewrite (Rminus_diag_eq _ _ E) in D.
  lra.
Qed.
