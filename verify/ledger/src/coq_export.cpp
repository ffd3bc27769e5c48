// GiNaC expressions printed as Coq terms over R, and the certificate of a claim (coq_export.hpp).

#include "coq_export.hpp"

#include <ginac/ginac.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace simpson::verify::detail {
namespace {

using GiNaC::ex;

/// A term Coq's field tactic cannot take: the export stops with this reason.
struct unsupported : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Prints one lemma's terms and collects what its statement quantifies over and assumes.
class coq_printer {
 public:
  std::string term(const ex& e) {
    if (GiNaC::is_a<GiNaC::numeric>(e)) return number(GiNaC::ex_to<GiNaC::numeric>(e));
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
      const std::string name = coq_identifier(GiNaC::ex_to<GiNaC::symbol>(e).get_name());
      symbols_.insert(name);
      return name;
    }
    // GiNaC orders the operands of a sum or a product, and picks the sign of a sum inside a product,
    // differently from run to run. Printed canonically (operands sorted by their text, each sum in a
    // product with the sign whose text is smaller and the other sign moved to the coefficient), the
    // same expression prints alike every time: the same scene gives the same files.
    if (GiNaC::is_a<GiNaC::add>(e)) return sum_text(e);
    if (GiNaC::is_a<GiNaC::mul>(e)) return product_text(e);
    if (GiNaC::is_a<GiNaC::power>(e)) {
      GiNaC::numeric sign(1);
      const std::string text = power_text(e, sign);
      return sign == 1 ? text : "((-1) * " + text + ")";
    }
    if (GiNaC::is_a<GiNaC::function>(e)) throw unsupported("the function " + GiNaC::ex_to<GiNaC::function>(e).get_name());
    throw unsupported("a term of another kind: " + to_text(e));
  }

  /// A sum in the sign whose text is smaller; `sign` is multiplied by −1 when that is −e.
  std::string signed_sum_text(const ex& e, GiNaC::numeric& sign) {
    const std::string plus = sum_text(e), minus = sum_text(e, true);
    if (minus < plus) {
      sign = -sign;
      return minus;
    }
    return plus;
  }

  /// A power with an integer exponent; a sum base in canonical sign, `sign` taking (−1)^n when flipped.
  std::string power_text(const ex& e, GiNaC::numeric& sign) {
    const ex exponent = e.op(1);
    if (!exponent.info(GiNaC::info_flags::integer)) throw unsupported("a non-integer power: " + to_text(e));
    const long n = GiNaC::ex_to<GiNaC::numeric>(exponent).to_long();
    GiNaC::numeric flip(1);
    const std::string base = GiNaC::is_a<GiNaC::add>(e.op(0)) ? signed_sum_text(e.op(0), flip) : term(e.op(0));
    if (flip != 1 && n % 2 != 0) sign = -sign;
    const std::string raised = std::labs(n) == 1 ? base : "(" + base + " ^ " + std::to_string(std::labs(n)) + ")";
    if (n > 0) return raised;
    assume_nonzero(e.op(0));
    return "(/ " + raised + ")";
  }

  /// A sum's text, or its negation's (each term negated: no expansion, the same structure).
  std::string sum_text(const ex& e, bool negated = false) {
    std::vector<std::string> parts;
    for (std::size_t k = 0; k < e.nops(); ++k) parts.push_back(term(negated ? ex(-e.op(k)) : e.op(k)));
    return joined(parts, " + ");
  }

  /// A product: its numeric coefficient (with the signs of the sums made canonical) first, then the
  /// other factors sorted by text.
  std::string product_text(const ex& e) {
    GiNaC::numeric coefficient(1);
    std::vector<std::string> parts;
    for (std::size_t k = 0; k < e.nops(); ++k) {
      const ex& f = e.op(k);
      if (GiNaC::is_a<GiNaC::numeric>(f)) {
        coefficient *= GiNaC::ex_to<GiNaC::numeric>(f);
      } else if (GiNaC::is_a<GiNaC::add>(f)) {
        parts.push_back(signed_sum_text(f, coefficient));
      } else if (GiNaC::is_a<GiNaC::power>(f)) {
        parts.push_back(power_text(f, coefficient));
      } else {
        parts.push_back(term(f));
      }
    }
    std::sort(parts.begin(), parts.end());
    if (coefficient != 1) parts.insert(parts.begin(), number(coefficient));
    if (parts.size() == 1) return parts.front();
    std::string out = "(";
    for (std::size_t k = 0; k < parts.size(); ++k) out += (k ? " * " : "") + parts[k];
    return out + ")";
  }

  const std::set<std::string>& symbols() const { return symbols_; }
  /// The nonzero hypotheses, sorted.
  std::vector<std::string> nonzero() const {
    std::vector<std::string> out = nonzero_;
    std::sort(out.begin(), out.end());
    return out;
  }

 private:
  static std::string joined(std::vector<std::string> parts, const char* separator) {
    std::sort(parts.begin(), parts.end());
    std::string out = "(";
    for (std::size_t k = 0; k < parts.size(); ++k) out += (k ? separator : "") + parts[k];
    return out + ")";
  }

  static std::string to_text(const ex& e) {
    std::ostringstream out;
    out << e;
    return out.str();
  }

  static std::string number(const GiNaC::numeric& v) {
    if (!v.is_rational()) throw unsupported("the number " + to_text(v));
    const std::string num = to_text(v.numer()), den = to_text(v.denom());
    const std::string text = v.is_integer() ? num : num + "/" + den;
    return v.is_integer() && v >= 0 ? text : "(" + text + ")";
  }

  /// A denominator: it and each of its factors is nonzero (field splits products into factors).
  void assume_nonzero(const ex& base) {
    add_nonzero(base);
    const ex factored = GiNaC::factor(base);
    const auto add_factor = [this](const ex& f) {
      const ex b = GiNaC::is_a<GiNaC::power>(f) ? f.op(0) : f;
      if (!GiNaC::is_a<GiNaC::numeric>(b)) add_nonzero(b);
    };
    if (GiNaC::is_a<GiNaC::mul>(factored)) {
      for (std::size_t k = 0; k < factored.nops(); ++k) add_factor(factored.op(k));
    } else {
      add_factor(factored);
    }
  }

  void add_nonzero(const ex& e) {
    coq_printer inner;
    GiNaC::numeric sign(1);  // X <> 0 and −X <> 0 say the same: the canonical sign
    const std::string text = (GiNaC::is_a<GiNaC::add>(e) ? inner.signed_sum_text(e, sign) : inner.term(e)) + " <> 0";
    symbols_.insert(inner.symbols_.begin(), inner.symbols_.end());
    for (const std::string& n : inner.nonzero_) push_unique(n);
    push_unique(text);
  }

  void push_unique(const std::string& text) {
    if (std::find(nonzero_.begin(), nonzero_.end(), text) == nonzero_.end()) nonzero_.push_back(text);
  }

  std::set<std::string> symbols_;
  std::vector<std::string> nonzero_;
};

/// One lemma: lhs = rhs for scalars.
std::string lemma(const std::string& name, const ex& lhs, const ex& rhs) {
  coq_printer p;
  const std::string left = p.term(lhs), right = p.term(rhs);
  std::string out = "Lemma " + name + " :";
  if (!p.symbols().empty()) {
    out += "\n  forall";
    for (const std::string& s : p.symbols()) out += " " + s;
    out += " : R,";
  }
  for (const char* positive : {"m", "h"}) {
    if (p.symbols().count(positive)) out += "\n  0 < " + std::string(positive) + " ->";
  }
  for (const std::string& h : p.nonzero()) out += "\n  " + h + " ->";
  out += "\n  " + left + "\n  = " + right + ".\n";
  out += "Proof.\n  intros.\n  field; repeat split; nonzero.\nQed.\n";
  return out;
}

}  // namespace

std::string coq_identifier(const std::string& name) {
  std::string out;
  for (const char c : name) out += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  if (out.empty() || std::isdigit(static_cast<unsigned char>(out.front()))) out = "v_" + out;
  return out;
}

coq_export coq_certificate(const std::string& claim_id, const std::string& statement, const std::vector<proof_goal>& goals) {
  coq_export out;
  std::string body, left_out;
  std::map<std::string, int> uses;
  try {
    for (const proof_goal& g : goals) {
      std::string base = coq_identifier(claim_id) + "_" + coq_identifier(g.name);
      const int seen = uses[base]++;
      if (seen > 0) base += "_" + std::to_string(seen + 1);  // a claim that checks two formulas: printed, printed_2
      if (!g.holds) {
        left_out += (left_out.empty() ? "" : ", ") + g.name;
        continue;
      }
      const ex l = g.lhs.evalm(), r = g.rhs.evalm();
      if (GiNaC::is_a<GiNaC::matrix>(l) != GiNaC::is_a<GiNaC::matrix>(r)) throw unsupported("a matrix equated with a scalar");
      if (GiNaC::is_a<GiNaC::matrix>(l)) {
        const GiNaC::matrix& L = GiNaC::ex_to<GiNaC::matrix>(l);
        const GiNaC::matrix& R = GiNaC::ex_to<GiNaC::matrix>(r);
        if (L.rows() != R.rows() || L.cols() != R.cols()) throw unsupported("matrices of different shapes");
        for (unsigned i = 0; i < L.rows(); ++i) {
          for (unsigned j = 0; j < L.cols(); ++j) {
            const std::string name = base + "_" + std::to_string(i + 1) + std::to_string(j + 1);
            body += "\n" + lemma(name, L(i, j), R(i, j));
            out.lemmas.push_back(name);
          }
        }
      } else {
        body += "\n" + lemma(base, l, r);
        out.lemmas.push_back(base);
      }
    }
  } catch (const unsupported& e) {
    out.lemmas.clear();
    out.not_exported = std::string("Coq's field tactic cannot state it: ") + e.what();
    return out;
  }
  if (out.lemmas.empty()) {
    out.not_exported = left_out.empty() ? "no identity decided by GiNaC" : "no identity holds (" + left_out + " refuted; negations are not exported yet)";
    return out;
  }
  std::string said = statement;  // a comment must not close early or nest
  for (const std::string& token : {std::string("(*"), std::string("*)")}) {
    for (std::size_t at = said.find(token); at != std::string::npos; at = said.find(token, at)) said.replace(at, 2, token == "(*" ? "( *" : "* )");
  }
  out.text = "(* Certificate of claim " + claim_id + ": " + said +
             "\n   Written by simpson-verify from the expressions its GiNaC kernel proved; check with coqc. *)\n"
             "Require Import Reals Field Lra Psatz.\nOpen Scope R_scope.\n\n"
             "(* field leaves side conditions X <> 0 in its own normal form: each is a hypothesis up to ring,\n"
             "   a positive hypothesis, or a power of one. *)\n"
             "Ltac nonzero :=\n"
             "  first [ assumption\n"
             "        | match goal with\n"
             "          | [ H : ?Y <> 0 |- ?X <> 0 ] => replace X with Y by ring; exact H\n"
             "          | [ H : 0 < ?Y |- ?X <> 0 ] => replace X with Y by ring; apply Rgt_not_eq; exact H\n"
             "          end\n"
             "        | apply pow_nonzero; nonzero ].\n" +
             (left_out.empty() ? "" : "(* Not stated here (GiNaC refuted them): " + left_out + ". *)\n") + body;
  return out;
}

}  // namespace simpson::verify::detail
