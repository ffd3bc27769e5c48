(* Refutation of claim qm-not-affine as printed: This interpolation is not linear if h > 0: the interpolating curve (q2t), its middle value q_m the harmonic one (qm-oscillateur-harmonique), is of degree 2 in t (for q_l + q_r != 0).
   The printed identity, for all values under its hypotheses, is false: each lemma is its negation,
   shown at one point where the two sides differ. Written by simpson-verify from the expressions
   its GiNaC kernel compared; check with coqc. *)
Require Import Reals Field Lra Psatz.
Open Scope R_scope.

(* At the counterexample point every hypothesis is a numeric fact (0 < 3, 24 + 2 ^ 2 * 3 ^ 2 <> 0). *)
Ltac premise := first [ lra | nra ].

Lemma qm_not_affine_linear_refuted :
  ~ (forall h omega q_l q_r theta : R,
  0 < h ->
  (((-1) * (h ^ 2) * (omega ^ 2)) + 8) <> 0 ->
  (((((-1) * theta) + 1) * (((-2) * theta) + 1) * q_l) + ((-1) * (((-2) * theta) + 1) * q_r * theta) + ((-16) * (((-1) * q_l) + ((-1) * q_r)) * (((-1) * theta) + 1) * (/ (((-1) * (h ^ 2) * (omega ^ 2)) + 8)) * theta))
  = (((((-1) * q_l) + q_r) * theta) + q_l)).
Proof.
  intro H.
  (* At h = (2), omega = (3), q_l = (5), q_r = (7), theta = (11) the two sides differ by (23760/7). *)
  assert (D : (((((-1) * (11)) + 1) * (((-2) * (11)) + 1) * (5)) + ((-1) * (((-2) * (11)) + 1) * (7) * (11)) + ((-16) * (((-1) * (5)) + ((-1) * (7))) * (((-1) * (11)) + 1) * (/ (((-1) * ((2) ^ 2) * ((3) ^ 2)) + 8)) * (11))) - (((((-1) * (5)) + (7)) * (11)) + (5)) = (23760/7)) by (field; premise).
  assert (E : (((((-1) * (11)) + 1) * (((-2) * (11)) + 1) * (5)) + ((-1) * (((-2) * (11)) + 1) * (7) * (11)) + ((-16) * (((-1) * (5)) + ((-1) * (7))) * (((-1) * (11)) + 1) * (/ (((-1) * ((2) ^ 2) * ((3) ^ 2)) + 8)) * (11))) = (((((-1) * (5)) + (7)) * (11)) + (5))) by (apply (H (2) (3) (5) (7) (11)); premise).
  rewrite (Rminus_diag_eq _ _ E) in D.
  lra.
Qed.
