#!/usr/bin/env python3
"""The verdicts of symplectic-euler-aligned.toml, derived in sympy from the mathematics, not from the harness.

Prints claim id -> {"verdict": ...}.
"""
import json
import sympy as sp

m, w, h = sp.symbols("m omega h", positive=True)
q, p, q0, p0 = sp.symbols("q p q_0 p_0", real=True)
out = {}


def verdict(ok, false="erratum"):
    return "holds" if ok else false


def zero(e):
    return sp.simplify(e) == 0


# As printed.
p1 = p0 - h * m * w**2 * q0
q1 = q0 + h / m * p1
Psi = sp.Matrix([[1 - w**2 * h**2, h / m], [-m * w**2 * h, 1]])
Hmod = p**2 / (2 * m) + m * w**2 * q**2 / 2 - h * w**2 / 2 * q * p

jacobian = sp.Matrix([[sp.diff(q1, q0), sp.diff(q1, p0)], [sp.diff(p1, q0), sp.diff(p1, p0)]])
out["the-map"] = {"verdict": verdict(zero((jacobian - Psi).norm() ** 2))}
out["determinant"] = {"verdict": verdict(zero(Psi.det() - 1), "fails")}

flow = sp.Matrix([[sp.cos(w * h), sp.sin(w * h) / (m * w)], [-m * w * sp.sin(w * h), sp.cos(w * h)]])
error = (Psi - flow).applyfunc(lambda e: sp.series(e, h, 0, 5).removeO())
lowest = min(min(k for (k,) in sp.Poly(e, h).monoms()) for e in error if not zero(e))
out["first-order"] = {"verdict": verdict(lowest - 1 == 1)}

th = sp.symbols("theta", positive=True)
trace = sp.simplify(Psi.trace().subs(w, th / h))
band = sp.solve_univariate_inequality(sp.Abs(trace) < 2, th, relational=False).intersect(sp.Interval.open(0, sp.oo))
out["stable"] = {"verdict": verdict(band == sp.Interval.open(0, 2))}

y = sp.Matrix([q, p])
out["modified-energy"] = {"verdict": verdict(zero(Hmod.subs({q: (Psi * y)[0], p: (Psi * y)[1]}, simultaneous=True) - Hmod))}

print(json.dumps(out, indent=1, sort_keys=True))
