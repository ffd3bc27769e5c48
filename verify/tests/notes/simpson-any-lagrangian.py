#!/usr/bin/env python3
"""The verdicts of simpson-any-lagrangian.toml, derived in sympy from the mathematics, not from the
harness: L stays a general function of two arguments throughout (sympy's undefined Function).

Prints claim id -> {"verdict": ...}; an erratum's wrong coefficient as {"printed": ..., "derived": ...}.
"""
import json
import sympy as sp

m, h, g, ell = sp.symbols("m h g ell", positive=True)
ql, qm, qr, th = sp.symbols("q_l q_m q_r theta", real=True)
Lqq, Lqv, Lvv = sp.Function("L_qq"), sp.Function("L_qv"), sp.Function("L_vv")  # second derivatives: L_qv = L_vq


class Lq(sp.Function):
    """L's partial derivative in q: its own partials are L_qq and L_qv."""

    def fdiff(self, argindex=1):
        return (Lqq if argindex == 1 else Lqv)(*self.args)


class Lv(sp.Function):
    """L's partial derivative in v: its own partials are L_qv (mixed partials agree) and L_vv."""

    def fdiff(self, argindex=1):
        return (Lqv if argindex == 1 else Lvv)(*self.args)


class L(sp.Function):
    """A general Lagrangian L(q, v): its partial derivatives are L_q and L_v, nothing else is known."""

    def fdiff(self, argindex=1):
        return (Lq if argindex == 1 else Lv)(*self.args)


out = {}


def verdict(ok, false="erratum"):
    return "holds" if ok else false


def zero(e):
    return sp.simplify(sp.expand(e)) == 0


# As printed.
phi = [(1 - th) * (1 - 2 * th), 4 * th * (1 - th), th * (2 * th - 1)]
interp = ql * phi[0] + qm * phi[1] + qr * phi[2]
vl, vm, vr = (-3 * ql + 4 * qm - qr) / h, (qr - ql) / h, (ql - 4 * qm + 3 * qr) / h
Lh = h / 6 * (L(ql, vl) + 4 * L(qm, vm) + L(qr, vr))
internal = Lv(ql, vl) - Lv(qr, vr) + h * Lq(qm, vm)
pl = sp.Rational(1, 2) * Lv(ql, vl) + sp.Rational(1, 3) * Lv(qm, vm) - sp.Rational(1, 6) * Lv(qr, vr) - h / 6 * Lq(ql, vl)
pr = -sp.Rational(1, 6) * Lv(ql, vl) + sp.Rational(2, 3) * Lv(qm, vm) + sp.Rational(1, 2) * Lv(qr, vr) + h / 6 * Lq(qr, vr)
pendulum = lambda q, v: m * ell**2 * v**2 / 2 + m * g * ell * sp.cos(q)
internal_pendulum = 4 * ell / h**2 * (ql - 2 * qm + qr) + 2 * g * sp.sin(qm)

# lagrangian: Simpson's rule on the action over [0, h], t = h theta, q the interpolant.
rule = lambda f: sp.Rational(1, 6) * (f(0) + 4 * f(sp.Rational(1, 2)) + f(1))
q_t, v_t = interp, sp.diff(interp, th) / h
derived = h * rule(lambda s: L(q_t.subs(th, s), sp.expand(v_t.subs(th, s))))
out["lagrangian"] = {"verdict": verdict(zero(derived - Lh))}

# internal-node: dL_h/dq_m = 0 is the printed equation up to a factor free of the nodes.
dqm = sp.diff(Lh, qm)
ratio = sp.simplify(dqm / internal)
out["internal-node"] = {"verdict": verdict(not any(ratio.has(s) for s in (ql, qm, qr)))}

# implicit: q_m inside L's partial derivatives (a general L): a nonlinear equation for it.
out["implicit"] = {"verdict": verdict(any(a.has(qm) for a in internal.atoms(Lq, Lv)))}

# momentum-left, momentum-right: p_l = -dL_h/dq_l, p_r = dL_h/dq_r, each as printed.
minus_dql = -sp.diff(Lh, ql)
out["momentum-left"] = {"verdict": verdict(zero(minus_dql - pl))}
if out["momentum-left"]["verdict"] == "erratum":  # the coefficient of dL/dv at the middle node
    probe = sp.Symbol("probe")
    derived_coefficient = sp.expand(minus_dql.subs(Lv(qm, vm), probe)).coeff(probe)
    out["momentum-left"]["coefficient"] = {"printed": "1/3", "derived": str(derived_coefficient)}
out["momentum-right"] = {"verdict": verdict(zero(sp.diff(Lh, qr) - pr))}

# symplectic: the step (q_l, p_l) -> (q_r, p_r) of the relations (internal), (pl), (pr), q_m solved
# along the way, by implicit differentiation: M = -A^{-1} B, det M = 1? As printed (with (pl)'s
# wrong coefficient) it is not; with (pl) as derived it is: a consequence of momentum-left.
pl_sym, pr_sym = sp.symbols("p_l p_r", real=True)


def step_det(p_left):
    relations = [internal, pl_sym - p_left, pr_sym - pr]
    unknowns, data = [qr, pr_sym, qm], [ql, pl_sym]
    A = sp.Matrix([[sp.diff(g, u) for u in unknowns] for g in relations])
    B = sp.Matrix([[sp.diff(g, d) for d in data] for g in relations])
    P = (A.adjugate() * B)[:2, :]  # = -det(A) M
    return sp.expand(P.det() - A.det() ** 2)  # 0 exactly when det M = 1


symplectic_as_printed = step_det(pl) == 0
out["symplectic"] = {"verdict": verdict(symplectic_as_printed)}
if not symplectic_as_printed and step_det(minus_dql) == 0:
    out["symplectic"]["follows_from"] = "momentum-left"

# pendulum-internal: dL_h/dq_m = 0 with L the pendulum's, up to a factor free of the nodes.
Lh_pendulum = h / 6 * (pendulum(ql, vl) + 4 * pendulum(qm, vm) + pendulum(qr, vr))
d_pendulum = sp.diff(Lh_pendulum, qm)
ratio = sp.simplify(d_pendulum / internal_pendulum)
ok = not any(ratio.has(s) for s in (ql, qm, qr))
out["pendulum-internal"] = {"verdict": verdict(ok)}
if not ok:  # scaled so that the coefficient of q_l is the printed 4 ell / h^2: that of sin(q_m)
    scale = sp.expand(d_pendulum).coeff(ql) / (4 * ell / h**2)
    right = sp.simplify(sp.expand(d_pendulum / scale).coeff(sp.sin(qm)))
    out["pendulum-internal"]["coefficient"] = {"printed": "2*g", "derived": str(right)}

print(json.dumps(out, indent=1, sort_keys=True))
