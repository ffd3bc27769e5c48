#!/usr/bin/env python3
"""The verdicts of midpoint-style-note.toml, derived in sympy from the mathematics, not from the harness.

Prints one JSON object: claim id -> {"verdict": ..., "follows_from": ...}. The verdict classes follow
docs/claims-file.md's shapes: a printed formula that differs from the one derived is an "erratum"
(its correction proved); a printed property that is false of the printed object (det = 1,
symplectic, a form it conserves when it conserves none) "fails"; a claim that fails as printed and
holds once the note's misprinted formula is replaced by the derived one "follows from" that
erratum's claim.
"""
import json
import sympy as sp

m, w, h = sp.symbols("m omega h", positive=True)
q0, q1, qm1, qj, qp1, q, p, r, x, t, v = sp.symbols("q_0 q_1 q_jm1 q_j q_jp1 q p r x t v", real=True)
V = sp.Function("V")
Vp = sp.Function("Vp")  # V', a function of its own: what V' of an argument is, for a general V
out = {}


def primes_as_Vp(e):
    """Every V'(a) that sympy writes as Subs(Derivative(V(x), x), x, a) (or Derivative(V(a), a)) as Vp(a)."""
    e = e.replace(lambda s: isinstance(s, sp.Subs) and isinstance(s.expr, sp.Derivative), lambda s: Vp(s.point[0]))
    return e.replace(lambda s: isinstance(s, sp.Derivative) and s.expr.func == V, lambda s: Vp(s.variables[0]))


def verdict(ok, false="erratum"):
    return "holds" if ok else false


def zero(e):
    return sp.simplify(e) == 0


# The note as printed (its TeX transcribed here by hand, once, and checked against the PDF of the note).
L_d = m / (2 * h) * (q1 - q0) ** 2 - h * V((q0 + q1) / 2)
printed_del = m * (qp1 - 2 * qj + qm1) / h**2 + sp.Rational(1, 2) * (Vp((qj + qp1) / 2) + Vp((qm1 + qj) / 2))
V_harmonic = sp.Rational(1, 2) * m * w**2 * x**2
printed_scheme = (qp1 - 2 * qj + qm1) / h**2 + w**2 / 4 * (qp1 + 2 * qj + qm1)
xq = w**2 * h**2 / 4
printed_map = sp.Matrix([[1 - xq, h / (2 * m)], [-m * w**2 * h, 1 - xq]]) / (1 + xq)  # the misprint: h/(2m)
printed_H = p**2 / (2 * m) + sp.Rational(1, 2) * m * w**2 * q**2
printed_trace = (2 - sp.Rational(1, 2) * w**2 * h**2) / (1 + xq)
printed_truncation = -w**4 * h**2 / 6 * qj  # + O(h^4)

# euler-lagrange: D2 L(q_{j-1}, q_j) + D1 L(q_j, q_{j+1}) is the printed equation times a factor free of the states.
D1 = sp.diff(L_d, q0)
D2 = sp.diff(L_d, q1)
del_derived = primes_as_Vp(D2.subs({q0: qm1, q1: qj}, simultaneous=True) + D1.subs({q0: qj, q1: qp1}, simultaneous=True))
ratio = sp.simplify(del_derived / printed_del)
out["euler-lagrange"] = {"verdict": verdict(not any(ratio.has(s) for s in (qm1, qj, qp1)))}

# consistency: on smooth states the printed scheme tends to m q'' + V'(q) = 0.
qf = sp.Function("qf")
on_smooth = printed_del.subs({qm1: qf(t - h), qj: qf(t), qp1: qf(t + h)}, simultaneous=True)
leading = sp.simplify(sp.series(on_smooth, h, 0, 1).removeO())
ode = m * sp.diff(qf(t), t, 2) + Vp(qf(t))
out["consistency"] = {"verdict": verdict(zero(leading - ode))}

# implicit: q_{j+1} inside V' makes the step a nonlinear equation for a general V; the note says implicit.
inside = any(a.has(qp1) for a in printed_del.atoms(Vp))
out["implicit"] = {"verdict": verdict(inside)}

# harmonic-force: F_j = -V'(q_j) with V harmonic, against the inline -m omega^2 q_j.
out["harmonic-force"] = {"verdict": verdict(zero(-sp.diff(V_harmonic, x).subs(x, qj) - (-m * w**2 * qj)))}

# harmonic-scheme: the printed harmonic scheme is the DEL with V harmonic, divided by a factor free of the states.
del_harmonic = printed_del.replace(Vp, sp.Lambda(x, sp.diff(V_harmonic, x)))
ratio = sp.simplify(printed_scheme / del_harmonic)
out["harmonic-scheme"] = {"verdict": verdict(not any(ratio.has(s) for s in (qm1, qj, qp1)))}

# one-step-map: p0 = -D1 L, p1 = D2 L, V harmonic, solved for (q1, p1) in (q0, p0).
p0, p1 = sp.symbols("p_0 p_1")
L_h = L_d.replace(V, sp.Lambda(x, V_harmonic)).doit()
sol = sp.solve([sp.Eq(p0, -sp.diff(L_h, q0)), sp.Eq(p1, sp.diff(L_h, q1))], [q1, p1], dict=True)[0]
derived_map = sp.Matrix([[sp.diff(sol[q1], q0), sp.diff(sol[q1], p0)], [sp.diff(sol[p1], q0), sp.diff(sol[p1], p0)]]).applyfunc(sp.simplify)
map_ok = zero((derived_map - printed_map).norm() ** 2)
out["one-step-map"] = {"verdict": verdict(map_ok)}

J = sp.Matrix([[0, 1], [-1, 0]])
y = sp.Matrix([q, p])


def conserves(M, H):
    return zero(H.subs({q: (M * y)[0], p: (M * y)[1]}, simultaneous=True) - H)


def conserves_some_form(M):
    a, b, c = sp.symbols("a b c")
    P = sp.Matrix([[a, b], [b, c]])
    eqs = list((M.T * P * M - P).applyfunc(sp.simplify))
    return any(s != {a: 0, b: 0, c: 0} for s in [sp.solve(eqs, [a, b, c], dict=True)[0]] if s) or \
        len(sp.solve(eqs, [a, b, c], dict=True)[0]) < 3


def property_claim(name, holds_printed, holds_corrected, false="fails"):
    entry = {"verdict": verdict(holds_printed, false)}
    if not holds_printed and not map_ok and holds_corrected:
        entry["follows_from"] = "one-step-map"
    out[name] = entry


property_claim("map-determinant", zero(printed_map.det() - 1), zero(derived_map.det() - 1))
property_claim("map-symplectic", zero((printed_map.T * J * printed_map - J).norm() ** 2), zero((derived_map.T * J * derived_map - J).norm() ** 2))
# conserved: an erratum (the form the map conserves) when the printed map conserves a quadratic form, else fails.
property_claim("energy-conserved", conserves(printed_map, printed_H), conserves(derived_map, printed_H),
               "erratum" if conserves_some_form(printed_map) else "fails")

# characteristic-equation: r^2 - tr(Phi_S) r + 1 against the scheme at (1, r, r^2), scaled to r^2's coefficient.
at_r = printed_scheme.subs({qm1: 1, qj: r, qp1: r**2}, simultaneous=True)
char_derived = sp.expand(at_r / sp.Poly(at_r, r).coeff_monomial(r**2))
out["characteristic-equation"] = {"verdict": verdict(zero(char_derived - (r**2 - printed_map.trace() * r + 1)))}

# trace: tr(Phi_S), the printed matrix's, against the printed value.
out["trace"] = {"verdict": verdict(zero(printed_map.trace() - printed_trace))}

# unconditionally-stable: for every omega h > 0 the roots are a complex pair of modulus 1 (discriminant < 0).
th = sp.symbols("theta", positive=True)
disc = sp.simplify((printed_map.trace() ** 2 - 4).subs(w, th / h))
out["unconditionally-stable"] = {"verdict": verdict(sp.ask(sp.Q.negative(disc), sp.Q.positive(th)) is True)}

# truncation: the DEL (V harmonic) divided by m on the exact solution through q_j, a series in h.
exact_prev = q * sp.cos(w * h) - v / w * sp.sin(w * h)
exact_next = q * sp.cos(w * h) + v / w * sp.sin(w * h)
on_exact = (del_harmonic / m).subs({qm1: exact_prev, qj: q, qp1: exact_next}, simultaneous=True)
series = sp.series(on_exact, h, 0, 4).removeO()
out["truncation"] = {"verdict": verdict(zero(series - printed_truncation.subs(qj, q)))}

# second-order: the leading power of the scheme on the exact solution is h^2, its q_{j+1} coefficient h^-2.
scheme_exact = printed_scheme.subs({qm1: exact_prev, qj: q, qp1: exact_next}, simultaneous=True)
lead = sp.Poly(sp.series(scheme_exact, h, 0, 6).removeO(), h).monoms()[-1][0]
order = lead - (-2) - 2
out["second-order"] = {"verdict": verdict(order == 2)}

print(json.dumps(out, indent=1, sort_keys=True))
