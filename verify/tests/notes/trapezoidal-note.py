#!/usr/bin/env python3
"""The verdicts of trapezoidal-note.toml, derived in sympy from the mathematics, not from the harness.

Prints claim id -> {"verdict": ..., "follows_from": ...}: the note's claims file records the same
verdicts as its `expected` (a regression guard), and this derivation is what they rest on.
"""
import json
import sympy as sp

m, w, h = sp.symbols("m omega h", positive=True)
q0, q1, p0, p1, qm1, qj, qp1, q, p, v, th, x = sp.symbols("q_0 q_1 p_0 p_1 q_jm1 q_j q_jp1 q p v theta x", real=True)
out = {}


def verdict(ok, false="erratum"):
    return "holds" if ok else false


def zero(e):
    return sp.simplify(e) == 0


# As printed (transcribed once, by hand; \half{x} is x/2, \om is omega).
interp = q0 * (1 - th) + q1 * th  # q(t), t = h theta
rule = lambda f: sp.Rational(1, 2) * (f(0) + f(1))
Ld = m / (2 * h) * (q1 - q0) ** 2 - h / 2 * (m * w**2 / 2 * q0**2 + m * w**2 / 2 * q1**2)
el_printed = m * (qp1 - 2 * qj + qm1) / h**2 + m * w**2 / 2 * qj
Phi = sp.Matrix([[1 - w**2 * h**2 / 2, h / m], [-m * w**2 * h * (1 - w**2 * h**2 / 4), 1 - w**2 * h**2 / 2]])
energy = p**2 / (2 * m) + m * w**2 / 2 * (1 - w**2 * h**2 / 2) * q**2
scheme = (qp1 - 2 * qj + qm1) / h**2 + w**2 * qj
truncation = w**4 * h**2 / 12 * q

# rule-exactness: exact through degree 1 only; the note says two.
degree = [sp.integrate(th**k, (th, 0, 1)) == rule(lambda s: s**k) for k in range(4)].index(False) - 1
out["rule-exactness"] = {"verdict": verdict(degree == 2)}

# lagrangian-from-the-rule: h times the rule on the action's integrand along the interpolant.
integrand = m / 2 * (sp.diff(interp, th) / h) ** 2 - m * w**2 / 2 * interp**2
out["lagrangian-from-the-rule"] = {"verdict": verdict(zero(h * rule(lambda s: integrand.subs(th, s)) - Ld))}

# discrete-euler-lagrange: D2 L(q_{j-1}, q_j) + D1 L(q_j, q_{j+1}) against the printed equation (a free factor).
derived = sp.diff(Ld, q1).subs({q0: qm1, q1: qj}, simultaneous=True) + sp.diff(Ld, q0).subs({q0: qj, q1: qp1}, simultaneous=True)
ratio = sp.simplify(derived / el_printed)
out["discrete-euler-lagrange"] = {"verdict": verdict(not any(ratio.has(s) for s in (qm1, qj, qp1)))}

# one-step-map: (q_1, p_1) from the printed update and momentum equal Phi (q_0, p_0).
q1_upd = (1 - w**2 * h**2 / 2) * q0 + h / m * p0
p1_upd = p0 - h * m * w**2 / 2 * (q0 + q1_upd)
out["one-step-map"] = {"verdict": verdict(zero((sp.Matrix([q1_upd, p1_upd]) - Phi * sp.Matrix([q0, p0])).norm() ** 2))}

# map-of-the-lagrangian: p_0 = -D1 L, p_1 = D2 L solved for (q_1, p_1).
sol = sp.solve([sp.Eq(p0, -sp.diff(Ld, q0)), sp.Eq(p1, sp.diff(Ld, q1))], [q1, p1], dict=True)[0]
derived_map = sp.Matrix([[sp.diff(sol[q1], q0), sp.diff(sol[q1], p0)], [sp.diff(sol[p1], q0), sp.diff(sol[p1], p0)]])
out["map-of-the-lagrangian"] = {"verdict": verdict(zero((derived_map - Phi).norm() ** 2))}

out["map-determinant"] = {"verdict": verdict(zero(Phi.det() - 1), "fails")}
J = sp.Matrix([[0, 1], [-1, 0]])
out["map-symplectic"] = {"verdict": verdict(zero((Phi.T * J * Phi - J).norm() ** 2), "fails")}

# modified-energy: the printed energy is not conserved (its q^2 coefficient should carry 1 - omega^2 h^2/4).
y = sp.Matrix([q, p])
out["modified-energy"] = {"verdict": verdict(zero(energy.subs({q: (Phi * y)[0], p: (Phi * y)[1]}, simultaneous=True) - energy))}

# energy-positive: 1 - omega^2 h^2/2 > 0 on 0 < omega h < 2? Only up to sqrt(2): an erratum, the
# printed energy's coefficient being the misprint's consequence (the record's typed link).
t = sp.symbols("t", positive=True)
positive = sp.solve_univariate_inequality(1 - t**2 / 2 > 0, t, relational=False).intersect(sp.Interval.open(0, sp.oo))
out["energy-positive"] = {"verdict": verdict(positive.is_superset(sp.Interval.open(0, 2))), "follows_from": "modified-energy"}

# second-order: the scheme on the exact solution is omega^4 h^2/12 q + O(h^4).
on_exact = scheme.subs({qm1: q * sp.cos(w * h) - v / w * sp.sin(w * h), qj: q, qp1: q * sp.cos(w * h) + v / w * sp.sin(w * h)}, simultaneous=True)
out["second-order"] = {"verdict": verdict(zero(sp.series(on_exact, h, 0, 4).removeO() - truncation))}
lead = min(k for (k,) in sp.Poly(sp.series(on_exact, h, 0, 8).removeO(), h).monoms())
out["stated-order"] = {"verdict": verdict(lead - (-2) - 2 == 2)}

# map-order: Phi minus the exact flow is O(h^3): order 2; the note says third.
flow = sp.Matrix([[sp.cos(w * h), sp.sin(w * h) / (m * w)], [-m * w * sp.sin(w * h), sp.cos(w * h)]])
error = (Phi - flow).applyfunc(lambda e: sp.series(e, h, 0, 6).removeO())
lowest = min(min(k for (k,) in sp.Poly(e, h).monoms()) for e in error if not zero(e))
out["map-order"] = {"verdict": verdict(lowest - 1 == 3)}

# stability-condition: the first band with |tr Phi| < 2 is 0 < omega h < 2, not 2 sqrt(2).
band = sp.solve_univariate_inequality(sp.Abs(sp.simplify(Phi.trace().subs(w, t / h))) < 2, t, relational=False).intersect(sp.Interval.open(0, sp.oo))
out["stability-condition"] = {"verdict": verdict(band == sp.Interval.open(0, 2 * sp.sqrt(2)))}

print(json.dumps(out, indent=1, sort_keys=True))
