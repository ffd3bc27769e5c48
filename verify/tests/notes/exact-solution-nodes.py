#!/usr/bin/env python3
"""The verdicts of exact-solution-nodes.toml, derived in sympy from the mathematics, not from the harness.

Prints claim id -> {"verdict": ...}. The exact solution through q_n = q(t_n), with velocity v:
q(t_n + k h) = q cos(k omega h) + (v/omega) sin(k omega h). A printed truncation error holds when
the scheme on the solution equals its terms (the solution at the nodes where it writes them) to its
printed order; else an erratum (the series is the correction).
"""
import json
import sympy as sp

w, h = sp.symbols("omega h", positive=True)
q, v, qn1, qn, qp1 = sp.symbols("q v q_nm1 q_n q_np1", real=True)


def at(k):
    """The exact solution at t_n + k h."""
    return q * sp.cos(k * w * h) + v / w * sp.sin(k * w * h)


def on_solution(expr):
    return expr.subs({qn1: at(-1), qn: at(0), qp1: at(1)}, simultaneous=True)


def holds_to(scheme, terms, order):
    gap = sp.series(on_solution(scheme) - terms, h, 0, order).removeO()
    return sp.simplify(gap) == 0


leapfrog = qp1 - 2 * qn + qn1 + w**2 * h**2 * qn
numerov = qp1 - 2 * qn + qn1 + w**2 * h**2 / 12 * (qp1 + 10 * qn + qn1)
out = {}

# linear in q_{n+1}: of an equation in its unknown, affine (degree 1, a constant term allowed).
out["leapfrog-linear"] = {"verdict": "holds" if sp.Poly(leapfrog, qp1).degree() == 1 else "erratum"}
# omega^4 h^4/12 q(t_n) + O(h^6).
out["leapfrog-truncation"] = {"verdict": "holds" if holds_to(leapfrog, w**4 * h**4 / 12 * at(0), 6) else "erratum"}
# -omega^2 h^2/12 (q(t_{n+1}) - 2 q(t_n) + q(t_{n-1})) + O(h^6): the neighbours are the solution's too.
out["leapfrog-truncation-nodes"] = {
    "verdict": "holds" if holds_to(leapfrog, -w**2 * h**2 / 12 * (at(1) - 2 * at(0) + at(-1)), 6) else "erratum"}
# Numerov: printed omega^6 h^6/120 q(t_n) + O(h^8); the series' leading term is omega^6 h^6/240 q.
out["numerov-truncation"] = {"verdict": "holds" if holds_to(numerov, w**6 * h**6 / 120 * at(0), 8) else "erratum"}
# omega^6 h^6/240 q(t_n + h) + O(h^7): q(t_n + h) = q + O(h), so the same leading term to h^6.
out["numerov-truncation-shift"] = {"verdict": "holds" if holds_to(numerov, w**6 * h**6 / 240 * at(1), 7) else "erratum"}
print(json.dumps(out, indent=1, sort_keys=True))
