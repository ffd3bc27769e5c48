#pragma once
// The proof shapes' test document and its claims file: a small note with a display for each shape,
// where it holds and where a weaker check would pass a wrong statement, and the fixture that runs one
// record on it (proof_shapes_test.cpp, prose_shapes_test.cpp).

#include <simpson/verify/claims_file.hpp>
#include <simpson/verify/ledger.hpp>
#include <simpson/verify/paper_reading.hpp>
#include <simpson/verify/printed_checks.hpp>

#include <gtest/gtest.h>

#include <string>

namespace simpson::verify::test {

inline paper_source document(const std::string& text) { return {"test.tex", without_comments(text), "", text}; }

inline const std::string shape_document = R"(\newcommand{\om}{\omega} \newcommand{\dd}{{\rm d}}
\title{Shapes under test}
\begin{equation}\label{ld} L_d = \frac{m}{2h} (q_1 - q_0)^2 - \frac{h m \om^2}{4} (q_0^2 + q_1^2) \end{equation}
\begin{equation}\label{el} m \frac{q_{j+1} - 2 q_j + q_{j-1}}{h^2} + m \om^2 q_j = 0 \end{equation}
\begin{equation}\label{elwrong} m \frac{q_{j+1} - 2 q_j + q_{j-1}}{h^2} + m \om^2 q_{j+1} = 0 \end{equation}
\begin{equation}\label{map} \Phi = \begin{pmatrix} 1 - \frac{\om^2 h^2}{2} & \frac{h}{m} \\
  - m \om^2 h \Big(1 - \frac{\om^2 h^2}{4}\Big) & 1 - \frac{\om^2 h^2}{2} \end{pmatrix} \end{equation}
\begin{equation}\label{mapwrong} \Psi = \begin{pmatrix} 1 - \frac{\om^2 h^2}{2} & \frac{h}{m} \\
  - m \om^2 h & 1 - \frac{\om^2 h^2}{2} \end{pmatrix} \end{equation}
\begin{equation}\label{mappq} \Phi = \begin{pmatrix} 1 - \frac{\om^2 h^2}{2} & - m \om^2 h \Big(1 - \frac{\om^2 h^2}{4}\Big) \\
  \frac{h}{m} & 1 - \frac{\om^2 h^2}{2} \end{pmatrix} \end{equation}
\begin{equation}\label{one} D = 1 \end{equation}
\begin{equation}\label{energy} H = \frac{p^2}{2m} + \frac{m \om^2}{2} \Big(1 - \frac{\om^2 h^2}{4}\Big) q^2 \end{equation}
\begin{equation}\label{energywrong} H = \frac{p^2}{2m} + \frac{m \om^2}{2} q^2 \end{equation}
\begin{equation}\label{sum} s = (a + b)^2 \end{equation}
\begin{equation}\label{expanded} t = a^2 + 2 a b + b^2 \end{equation}
Stable for $0 < \om h < 2$. Also stable for $0 < \om h < 2 \sqrt{2}$. And for $0 < \om h < 1$.
\begin{equation}\label{ldm} L_d = \frac{m}{h} \Big( (q_m - q_0)^2 + (q_1 - q_m)^2 \Big) \end{equation}
\begin{equation}\label{free} F = \begin{pmatrix} 1 & \frac{h}{m} \\ 0 & 1 \end{pmatrix} \end{equation}
\begin{equation}\label{internal} q_0 - 2 q_m + q_1 = 0 \end{equation}
\begin{equation}\label{internalwrong} q_0 - q_m + q_1 = 0 \end{equation}
\begin{equation}\label{sv} \frac{q_{j+1} - 2 q_j + q_{j-1}}{h^2} + \om^2 q_j = 0 \end{equation}
\begin{equation}\label{trunc} \frac{\om^4 h^2}{12} q_j + {\rm O}(h^4) \end{equation}
\begin{equation}\label{truncwrong} \frac{\om^4 h^2}{24} q_j + {\rm O}(h^4) \end{equation}
\begin{equation}\label{truncshort} {\rm O}(h^4) \end{equation}
\begin{equation}\label{steep} \frac{q_{j+1} - 2 q_j + q_{j-1}}{h^6} + \frac{\om^2 q_j}{h^4} - \frac{\om^4 q_j}{12 h^2} = 0 \end{equation}
\begin{equation}\label{steepzero} 0 + {\rm O}(h^2) \end{equation}
\begin{equation}\label{potential energy} V(q) = \frac{k}{2} q^2 \end{equation}
\begin{equation}\label{force} F = - {{\partial V}\over{\partial q}}(x) \end{equation}
\begin{equation}\label{balance} k q - 2 = 0 \end{equation}
\begin{equation}\label{square} q^2 - 4 = 0 \end{equation}
\begin{equation}\label{pnext} p_1 = \frac{m}{h} (q_{j+1} - q_j) - \frac{h m \om^2}{2} q_{j+1} \end{equation}
\begin{equation}\label{momsys} p_{j+1} - p_j = - \frac{h m \om^2}{2} (q_{j+1} + q_j) \,,\,\, \Big(1 - \frac{\om^2 h^2}{4}\Big) \frac{q_{j+1} - q_j}{h} = \frac{p_{j+1} + p_j}{2 m} \end{equation}
\begin{equation}\label{momsysmid} p_{j+1} - p_j = - \frac{h m \om^2}{2} (q_{j+1} + q_j) \,,\,\, \frac{q_{j+1} - q_j}{h} = \frac{p_{j+1} + p_j}{2 m} \end{equation}
This scheme is of fourth order. The same scheme is of second order.
Coefficient $1 - \frac{\om^2 h^2}{4}$ positive on $0 < \om h < 2$, but not on the wide $0 < \om h < 3$.
That map is symplectic indeed. This map is not symplectic, some say. Another map is wonderful here.
Its roots solve $r^2 - (2 - \om^2 h^2) r + c = 0$. Misprinted, $r^2 - (2 + \om^2 h^2) r + c = 0$. With the constant, $r^2 - (2 - \om^2 h^2) r + 2 = 0$.
\begin{equation}\label{disc} P = \frac{\om^2 h^2}{36} (\om^2 h^2 - 4) (\om^2 h^2 - 9) \end{equation}
\begin{equation}\label{disc2} Q = (\om^2 h^2 - 4) (\om^2 h^2 - 9) \end{equation}
First, on $0 < \om h < 2$ all the factors of $P$ are negative and $P > 0$.
Then, on $0 < \om h < 2$ all the factors of $Q$ are negative and $Q > 0$.
Wide, on $0 < \om h < 3$ all the factors of $Q$ are negative and $Q > 0$.
Last, on $0 < \om h < 2$ all the factors of $P$ are positive and $P > 0$.
Narrow: on $0 < \om h < 2$ the equation has two complex conjugate roots, of product equal to 1, and the scheme is stable.
Wide: on $0 < \om h < 3$ the equation has two complex conjugate roots, of product equal to 1, and the scheme is stable.
Real: on $0 < \om h < 2$ the equation has two real roots, of product equal to 1, and the scheme is stable.
Double: on $0 < \om h < 2$ the equation has two complex conjugate roots, of product equal to 2, and the scheme is stable.
Criterion one: the scheme is stable when the roots are of modulus smaller than 1.
Criterion two: the scheme is stable when the roots are of modulus at most 1 and simple.
Criterion three: the scheme is stable when the roots are of modulus at most 1.
\begin{equation}\label{phis} \varphi_0(\theta) = 1 - \theta \,,\,\, \varphi_1(\theta) = \theta \end{equation}
\begin{equation}\label{linear} q(t) = a \, \varphi_0(\theta) + b \, \varphi_1(\theta) \end{equation}
With $t = h \, \theta$ the nodes are $q(0) = a$ and $q(h) = b$, not $q(h) = a$; one side alone, $q(h)$.
\begin{equation}\label{slope} g = {{\dd q}\over{\dd t}}(0) = \frac{b - a}{h} = {{\dd q}\over{\dd t}} \end{equation}
\begin{equation}\label{trapezoid} \int_0^1 \psi(x) \, \dd x \simeq \frac{1}{2} \big( \psi(0) + \psi(1) \big) \end{equation}
\begin{equation}\label{midpoint} \int_0^h \psi(t) \, \dd t \simeq h \, \psi\Big( \frac{h}{2} \Big) \end{equation}
Trapezoids are exact for polynomials of degree one. Trapezoids, some say, are exact for polynomials of degree two.
Trapezoids, said loosely, are exact for polynomials of degree zero. Trapezoids are, at best, exact for polynomials of degree at most 1.
One step's action, $\int_0^h \Big[ \frac{m}{2} \Big( {{\dd q}\over{\dd t}} \Big)^2 - V(q) \Big] \, \dd t$, by a rule:
\begin{equation}\label{ltrap} L = \frac{m}{2 h} (b - a)^2 - \frac{h}{2} \big( V(a) + V(b) \big) \end{equation}
\begin{equation}\label{lmid} L = \frac{m}{2 h} (b - a)^2 - h \, V\Big( \frac{a + b}{2} \Big) \end{equation}
\begin{equation}\label{ode} {{\dd^2 q}\over{\dd t^2}} + \om^2 q = 0 \end{equation}
\begin{equation}\label{odewrong} {{\dd^2 q}\over{\dd t^2}} + 2 \om^2 q = 0 \end{equation}
\begin{equation}\label{euler} p_{j+1} - p_j = - h \om^2 q_{j+1} \,,\,\, q_{j+1} - q_j = h \, p_j \end{equation}
\begin{equation}\label{hamilton} {{\dd p}\over{\dd t}} + \om^2 q = 0 \,,\,\, {{\dd q}\over{\dd t}} = p \end{equation}
For $0 \leq t \leq T$ in $N$ elements, $h = \frac{T}{N}$, the nodes at $t_j = j \, h$ and the action
\begin{equation}\label{action} S = \sum_{j=0}^{N-1} L_d(q_j, q_{j+1}) \end{equation}
\begin{equation}\label{actionshort} S = \sum_{j=1}^{N-1} L_d(q_j, q_{j+1}) \end{equation}
\begin{equation}\label{actionlong} S = \sum_{j=0}^{N} L_d(q_j, q_{j+1}) \end{equation}
\begin{equation}\label{average} \frac{q_{j+1} - 2 q_j + q_{j-1}}{h^2} + \frac{\om^2}{4} (q_{j+1} + 2 q_j + q_{j-1}) = 0 \end{equation}
The average scheme is linearly stable. Averaging is an unconditionally stable method. Averaging, some say, is a conditionally stable method.
The leapfrog scheme is stable. Leapfrog is an unconditionally stable method.
Leapfrog, with a small step, is conditionally stable. Averaging, loosely, is conditionally stable.
\begin{equation}\label{antidamped} \frac{q_{j+1} - 2 q_j + q_{j-1}}{h^2} - \om^2 q_j = 0 \end{equation}
Antidamping, with a small step, is conditionally stable. Antidamping is unstable.
\begin{equation}\label{taylorup} q_{j+1} = q_j + h {{\dd q}\over{\dd t}} + \frac{h^2}{2} {{\dd^2 q}\over{\dd t^2}} + {\rm O}(h^3) \end{equation}
\begin{equation}\label{taylorwrong} q_{j-1} = q_j - h {{\dd q}\over{\dd t}} - \frac{h^2}{2} {{\dd^2 q}\over{\dd t^2}} + {\rm O}(h^3) \end{equation}
\begin{equation}\label{taylorup3} q_{j+1} = q_j + h {{\dd q}\over{\dd t}} + \frac{h^2}{2} {{\dd^2 q}\over{\dd t^2}} + \frac{h^3}{6} {{\dd^3 q}\over{\dd t^2}} + {\rm O}(h^4) \end{equation}
\begin{equation}\label{taylordown3} q_{j-1} = q_j - h {{\dd q}\over{\dd t}} + \frac{h^2}{2} {{\dd^2 q}\over{\dd t^2}} - \frac{h^3}{6} {{\dd^3 q}\over{\dd t^2}} + {\rm O}(h^4) \end{equation}
Leapfrog discretizes the equation to second order. Leapfrog, loosely, discretizes it to fourth order.
A generic map $\Psi = \begin{pmatrix} u & v \\ w & z \end{pmatrix}$. It conserves $K = \frac{1}{2} w q^2 - \frac{1}{2} v p^2$, and not $K = \frac{1}{2} w q^2 - \frac{1}{2} z p^2$.
A map of one entry, $\Psi = \begin{pmatrix} u \end{pmatrix}$; a map with a number, $\Psi = \begin{pmatrix} u & 2 \\ w & z \end{pmatrix}$.
\begin{equation}\label{slopemiddle} g = {{\dd q}\over{\dd t}}(0) = \frac{b - a}{2 h} = \frac{b - a}{h} \end{equation}
\begin{equation}\label{damped} 2 q_{j+1} - 3 q_j + q_{j-1} = 0 \end{equation}
Written $a r^2 + b r + c = 0$ with $a = 2$ and $b = -3$, its discriminant $\Delta \equiv b^2 - 4 a c$ is $\Delta = 1$, not $\Delta = -7$; misdefined, $\Delta \equiv b^2 - 2 a c$.
A square map $\Psi = \begin{pmatrix} u & v \\ w & s \end{pmatrix}$ and a form $F = \frac{1}{2} a q^2 + b q p + \frac{1}{2} c p^2$.
\begin{equation}\label{invsys} G \begin{pmatrix} a \\ b \\ c \end{pmatrix} = \begin{pmatrix} \frac{u^2 - 1}{2} & u w & \frac{w^2}{2} \\ u v & u s + v w - 1 & w s \\
  \frac{v^2}{2} & v s & \frac{s^2 - 1}{2} \end{pmatrix} \begin{pmatrix} a \\ b \\ c \end{pmatrix} = 0 \end{equation}
\begin{equation}\label{invsyswrong} G \begin{pmatrix} a \\ b \\ c \end{pmatrix} = \begin{pmatrix} \frac{u^2 - 1}{2} & u w & \frac{w^2}{2} \\ u v & u s + v w - 1 & w s \\
  \frac{v^2}{2} & v s & \frac{w^2 - 1}{2} \end{pmatrix} \begin{pmatrix} a \\ b \\ c \end{pmatrix} = 0 \end{equation}
Its determinant is $D = \frac{1}{4} (u s - v w - 1) (1 - u - s + u s - v w) (1 + u + s + u s - v w)$; without the quarter,
$D = (u s - v w - 1) (1 - u - s + u s - v w) (1 + u + s + u s - v w)$.
\begin{equation}\label{invsysrankone} G \begin{pmatrix} a \\ b \\ c \end{pmatrix} = \begin{pmatrix} \frac{u^2 - 1}{2} & u w & \frac{w^2}{2} \\ \frac{u^2 - 1}{2} & u w & \frac{w^2}{2} \\
  \frac{u^2 - 1}{2} & u w & \frac{w^2}{2} \end{pmatrix} \begin{pmatrix} a \\ b \\ c \end{pmatrix} = 0 \end{equation}
With equal diagonal $u = s$ we find $b = 0$, but not only $c = 0$; a cube, $K = q^3$, is no such form.
Of unit determinant, $u s - v w = 1$; on a circle, $u^2 + s^2 = 1$.
\begin{equation}\label{newmarkmap} \Phi = \frac{1}{1 + \frac{\om^2 h^2}{4}} \begin{pmatrix} 1 - \frac{\om^2 h^2}{4} & \frac{h}{m} \\
  - m \om^2 h & 1 - \frac{\om^2 h^2}{4} \end{pmatrix} \end{equation}
\begin{equation}\label{singularmap} \Phi = \frac{1}{1 - \frac{\om^2 h^2}{4}} \begin{pmatrix} 1 & h \\ 0 & 1 \end{pmatrix} \end{equation}
Written as (\ref{map}), leapfrog is an explicit scheme. Written as (\ref{newmarkmap}), the trapezoidal rule is an explicit scheme.
Said otherwise, the trapezoidal rule is an implicit scheme. Said otherwise, leapfrog is an implicit scheme. Written as (\ref{singularmap}), the backward rule is an explicit scheme.
\begin{equation}\label{midnode} q_m = \frac{1}{1 - \frac{\om^2 h^2}{8}} \frac{q_0 + q_1}{2} \end{equation}
\begin{equation}\label{squarenode} q_m = \frac{q_0^2 + q_1^2}{q_0 + q_1} \end{equation}
This node is not linear in the ends. That node is linear in the ends. Squared, the node is linear in the ends.
\begin{equation}\label{shearedmap} \Phi = \begin{pmatrix} 1 - \frac{\om^2 h^2}{2} + \frac{\om^4 h^4}{24} &
  \frac{1}{1 + \om^2 h^2} \Big( \frac{h}{m} - \frac{\om^2 h^3}{6 m} \Big) \\
  (1 + \om^2 h^2) \Big( - m \om^2 h + \frac{m \om^4 h^3}{6} \Big) & 1 - \frac{\om^2 h^2}{2} + \frac{\om^4 h^4}{24} \end{pmatrix} \end{equation}
Leapfrog, (\ref{map}), is second order accurate for state and momentum. Its twin (\ref{mappq}) is second order accurate too.
Leapfrog, once more, is third order accurate. Sheared, (\ref{shearedmap}) is fourth order accurate.
\begin{equation}\label{removable} \frac{x^2 - 1}{x - 1} - 2 = 0 \end{equation}
\begin{equation}\label{pole} \frac{x}{x - 1} - 1 = 0 \end{equation}
)";

inline const std::string declarations = R"(
[document]
title = "Shapes under test"
[symbols]
positive = ['m', '\omega', 'h']
real = ['q', 'p', 'q_0', 'q_1', 'q_m', 'p_0', 'p_1', 'q_{j-1}', 'q_j', 'q_{j+1}', 'a', 'b', 'k', 'x', 'r', 'c', '\theta', 'p_j', 'p_{j+1}', 't', 'T', 'N', 'j',
        'u', 'v', 'w', 's']
functions = ['\psi', 'f', 'V', 'q', 'L_d', '\varphi_0', '\varphi_1']
)";

inline std::string record(const std::string& id, const std::string& shape, const std::string& with) {
  return "[[claim]]\nid = \"" + id + "\"\nsection = \"1\"\nequation = \"x\"\nstatement = 'x'\nmethods = [\"exact\"]\nshape = \"" + shape +
         "\"\nwith = " + with + "\n";
}

/// The verdict of one record, its file's declarations `declared`, run on a document.
class RecordOnADocument : public ::testing::Test {
 protected:
  claim_result run_declared(const std::string& declared, const std::string& shape, const std::string& with, const std::string& text) {
    book_ = read_claim_book(declared + record("under-test", shape, with), "test.toml");
    reading_ = read_note(document(text));
    check_claims_file_formulas(book_, reading_.source);
    run_context ctx;
    ctx.paper = &reading_;
    ctx.book = &book_;
    return check_claim(book_.find("under-test"), ctx);
  }

  claim_book book_;
  paper_reading reading_;
};

/// The verdict of each record run on shape_document.
class ShapesOnADocument : public RecordOnADocument {
 protected:
  claim_result run(const std::string& shape, const std::string& with, const std::string& text = shape_document) {
    return run_declared(declarations, shape, with, text);
  }
};

}  // namespace simpson::verify::test
