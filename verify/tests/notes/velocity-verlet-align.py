#!/usr/bin/env python3
"""The verdicts of velocity-verlet-align.toml, derived in sympy from the mathematics, not from the harness.

Prints claim id -> {"verdict": ...}. Classes as docs/claims-file.md's shapes give them: a printed
formula or statement that differs from the one derived is an "erratum" (the correction proved).
"""
import json
import sympy as sp

w, h, T, N = sp.symbols("omega h T N", positive=True)
q0, v0, q, v, j = sp.symbols("q_0 v_0 q v j", real=True)
out = {}


def verdict(ok, false="erratum"):
    return "holds" if ok else false


def zero(e):
    return sp.simplify(e) == 0


# As printed (transcribed once, by hand).
v_half = v0 - h / 2 * w**2 * q0
q1 = q0 + h * v_half
v1 = v_half - h / 2 * w**2 * q1
M = sp.Matrix([[1 - w**2 * h**2 / 2, h], [-w**2 * h * (1 - w**2 * h**2 / 4), 1 - w**2 * h**2 / 2]])
E = sp.Rational(1, 2) * v**2 + sp.Rational(1, 2) * w**2 * q**2

# matrix-form: the Jacobian of (q_1, v_1) in (q_0, v_0) is M.
jacobian = sp.Matrix([[sp.diff(q1, q0), sp.diff(q1, v0)], [sp.diff(v1, q0), sp.diff(v1, v0)]])
out["matrix-form"] = {"verdict": verdict(zero((jacobian - M).norm() ** 2))}

# determinant: det M = 1 (a property of the printed matrix: false would be "fails").
out["determinant"] = {"verdict": verdict(zero(M.det() - 1), "fails")}

# stable: det 1, and |tr M| < 2 exactly on 0 < omega h < 2 (its first band).
th = sp.symbols("theta", positive=True)
trace = sp.simplify(M.trace().subs(w, th / h))
band = sp.solve_univariate_inequality(sp.Abs(trace) < 2, th, relational=False).intersect(sp.Interval.open(0, sp.oo))
out["stable"] = {"verdict": verdict(band == sp.Interval.open(0, 2))}

# second-order: M minus the exact flow of q'' = -omega^2 q over one step is O(h^3), not O(h^4).
flow = sp.Matrix([[sp.cos(w * h), sp.sin(w * h) / w], [-w * sp.sin(w * h), sp.cos(w * h)]])
error = (M - flow).applyfunc(lambda e: sp.series(e, h, 0, 5).removeO())
lowest = min(min(k for (k,) in sp.Poly(e, h).monoms()) for e in error if not zero(e))
out["second-order"] = {"verdict": verdict(lowest - 1 == 2)}

# energy: E(M y) = E(y)? When not, the map conserves another quadratic form: an erratum, corrected.
y = sp.Matrix([q, v])
Ey = E.subs({q: (M * y)[0], v: (M * y)[1]}, simultaneous=True)
out["energy"] = {"verdict": verdict(zero(Ey - E))}

# action-range: the elements of [0, T] with t_j = j h, h = T/N, run from the j with t_j = 0 to the j
# with t_{j+1} = T: 0 to N - 1; the sentence says 1 to N.
t = j * T / N
first = sp.solve(sp.Eq(t, 0), j)[0]
last = sp.solve(sp.Eq(t.subs(j, j + 1), T), j)[0]
out["action-range"] = {"verdict": verdict(first == 1 and zero(last - N))}

print(json.dumps(out, indent=1, sort_keys=True))
