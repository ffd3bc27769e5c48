#!/usr/bin/env python3
"""The verdicts of implicit-midpoint-macros.toml, derived in sympy from the mathematics, not from the harness.

Prints claim id -> {"verdict": ...}.
"""
import json
import sympy as sp

m, w, h = sp.symbols("m omega h", positive=True)
q, p, q0, q1, p0, p1 = sp.symbols("q p q_0 q_1 p_0 p_1", real=True)
Vp = sp.Function("Vp")  # V', for a general V
out = {}


def verdict(ok, false="erratum"):
    return "holds" if ok else false


def zero(e):
    return sp.simplify(e) == 0


# As printed (the note's macros expanded by hand: \avg{x} is x/2, \avg[4]{x} x/4, \x omega^2 h^2).
H = p**2 / (2 * m) + m * w**2 / 2 * q**2
dHdp = p / m
momentum_update = p1 - p0 + h * Vp((q0 + q1) / 2)
x = w**2 * h**2
R = sp.Matrix([[1 - x / 4, h / m], [-m * w**2 * h, 1 - x / 4]]) / (1 + x / 4)
trR = 2 * (1 - x / 4) / (1 + x / 4)

out["hamilton-velocity"] = {"verdict": verdict(zero(sp.diff(H, p) - dHdp))}
# implicit: q_1 inside V' (a general V): the step solves a nonlinear equation; the note says implicit.
out["implicit"] = {"verdict": verdict(any(a.has(q1) for a in momentum_update.atoms(Vp)))}
out["trace"] = {"verdict": verdict(zero(R.trace() - trR))}
out["determinant"] = {"verdict": verdict(zero(R.det() - 1), "fails")}
y = sp.Matrix([q, p])
out["energy"] = {"verdict": verdict(zero(H.subs({q: (R * y)[0], p: (R * y)[1]}, simultaneous=True) - H))}

# The map R is the rule's for the harmonic V: solve the two printed equations for (q_1, p_1).
sol = sp.solve([q1 - q0 - h / m * (p0 + p1) / 2, momentum_update.replace(Vp, sp.Lambda(q, m * w**2 * q))], [q1, p1], dict=True)[0]
derived = sp.Matrix([[sp.diff(sol[q1], q0), sp.diff(sol[q1], p0)], [sp.diff(sol[p1], q0), sp.diff(sol[p1], p0)]])
assert zero((derived - R).norm() ** 2), "the note's R is the rule's map: a claim the note does not state, checked here as its premise"

print(json.dumps(out, indent=1, sort_keys=True))
