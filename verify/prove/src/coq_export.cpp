// GiNaC expressions printed as Coq terms over R, and the certificate of a claim (coq_export.hpp).

#include <simpson/prove/coq_export.hpp>

#include <simpson/verify/tex_math.hpp>

#include <ginac/ginac.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <tuple>

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
      const std::string name = coq_symbol_identifier(GiNaC::ex_to<GiNaC::symbol>(e).get_name());
      note_symbol(name, e);
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
    if (GiNaC::is_a<GiNaC::function>(e)) return application_text(e);
    throw unsupported("a term of another kind: " + to_text(e));
  }

  /// An uninterpreted function of the paper (V, q, L, ...) applied, `(V x)`, `(L q v)`; its k-th
  /// derivative is a function of its own, `(dV x)`, `(d2V x)`, and a partial derivative of a function
  /// of several arguments by its slots too, `(d_1_L q v)`. The lemma quantifies over each: an identity GiNaC proved
  /// with V(x) and V'(x) as independent atoms holds for every pair of functions, V' among them.
  std::string application_text(const ex& e) {
    const GiNaC::function& f = GiNaC::ex_to<GiNaC::function>(e);
    std::string name = f.get_name();
    if (!is_reader_function(e)) throw unsupported("the function " + name);
    if (GiNaC::is_a<GiNaC::fderivative>(e)) {
      const GiNaC::paramset& slots = GiNaC::ex_to<GiNaC::fderivative>(e).derivatives();
      if (f.nops() == 1) {
        name = "d" + (slots.size() > 1 ? std::to_string(slots.size()) : std::string()) + name;
      } else {  // a partial derivative of L(q, v) by its slots, D[0,1](L): a function of its own, d_0_1_L
        std::string by;
        for (const unsigned slot : slots) by += "_" + std::to_string(slot);
        name = "d" + by + "_" + name;
      }
    }
    const std::string id = coq_identifier(name);
    functions_[id] = f.nops();
    std::string out = "(" + id;
    // field takes (V a) and (V b) as different atoms unless a and b print alike: each argument in
    // GiNaC's normal form (the same real number), so that equal arguments are one atom.
    for (std::size_t k = 0; k < f.nops(); ++k) out += " " + term(GiNaC::normal(f.op(k)));
    return out + ")";
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

  /// A rational number as a Coq term (negative and fractional ones in parentheses).
  static std::string number(const GiNaC::numeric& v) {
    if (!v.is_rational()) throw unsupported("the number " + to_text(v));
    const std::string num = to_text(v.numer()), den = to_text(v.denom());
    const std::string text = v.is_integer() ? num : num + "/" + den;
    return v.is_integer() && v >= 0 ? text : "(" + text + ")";
  }

  /// The symbols by their Coq names (sorted).
  const std::map<std::string, ex>& symbols() const { return symbols_; }
  /// The functions applied, by their Coq names, with their arities.
  const std::map<std::string, std::size_t>& functions() const { return functions_; }
  /// The nonzero hypotheses, sorted by text.
  std::vector<std::string> nonzero() const {
    std::vector<std::string> out;
    for (const auto& [text, e] : nonzero_) out.push_back(text);
    std::sort(out.begin(), out.end());
    return out;
  }
  /// The expressions the nonzero hypotheses are about.
  std::vector<ex> nonzero_expressions() const {
    std::vector<ex> out;
    for (const auto& [text, e] : nonzero_) out.push_back(e);
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
    for (const auto& [name, symbol] : inner.symbols_) note_symbol(name, symbol);
    functions_.insert(inner.functions_.begin(), inner.functions_.end());
    for (const auto& [n, inner_e] : inner.nonzero_) push_unique(n, inner_e);
    push_unique(text, e);
  }

  /// Two different symbols printed as one identifier would make the lemma quantify over one variable
  /// where the statement has two: a special case of it (q_{j-1} = q_{j+1}), proved in its place.
  void note_symbol(const std::string& name, const ex& symbol) {
    const auto [at, inserted] = symbols_.emplace(name, symbol);
    if (!inserted && !at->second.is_equal(symbol)) {
      throw unsupported("two symbols, " + to_text(at->second) + " and " + to_text(symbol) + ", would both be " + name + " in Coq");
    }
  }

  void push_unique(const std::string& text, const ex& e) {
    const auto same = [&text](const std::pair<std::string, ex>& n) { return n.first == text; };
    if (std::find_if(nonzero_.begin(), nonzero_.end(), same) == nonzero_.end()) nonzero_.emplace_back(text, e);
  }

  std::map<std::string, ex> symbols_;
  std::map<std::string, std::size_t> functions_;
  std::vector<std::pair<std::string, ex>> nonzero_;
};

/// One identity as Coq states it: what it quantifies over and assumes, and its two sides.
struct coq_statement {
  std::map<std::string, ex> symbols;  // by Coq name, sorted
  std::vector<ex> nonzero;            // the expressions assumed nonzero
  std::string premises;               // "forall ... : R," and the hypotheses, each on its own line
  std::string left, right;
};

/// What a lemma quantifies over and assumes, from everything `p` printed: its symbols, 0 < m and
/// 0 < h, and each denominator nonzero, each on its own line.
std::string premises_text(const coq_printer& p) {
  std::string out;
  std::map<std::size_t, std::string> by_arity;  // the functions' binders, one group per type
  for (const auto& [name, arity] : p.functions()) {
    if (p.symbols().count(name)) throw unsupported("a function and a symbol both named " + name);
    by_arity[arity] += " " + name;
  }
  if (!by_arity.empty()) {
    out += "\n  forall";
    for (const auto& [arity, names] : by_arity) {
      std::string type;
      for (std::size_t k = 0; k < arity; ++k) type += "R -> ";
      out += " (" + names.substr(1) + " : " + type + "R)";
    }
    if (!p.symbols().empty()) {
      out += " (";
      for (const auto& [name, symbol] : p.symbols()) out += name + " ";
      out += ": R)";
    }
    out += ",";
  } else if (!p.symbols().empty()) {
    out += "\n  forall";
    for (const auto& [name, symbol] : p.symbols()) out += " " + name;
    out += " : R,";
  }
  for (const char* positive : {"m", "h"}) {
    if (p.symbols().count(positive)) out += "\n  0 < " + std::string(positive) + " ->";
  }
  for (const std::string& h : p.nonzero()) out += "\n  " + h + " ->";
  return out;
}

coq_statement stated(const ex& lhs, const ex& rhs) {
  coq_printer p;
  coq_statement s;
  s.left = p.term(lhs);
  s.right = p.term(rhs);
  s.symbols = p.symbols();
  s.nonzero = p.nonzero_expressions();
  s.premises = premises_text(p);
  return s;
}

/// A sign lemma: 0 < e for each e of the region -> lhs < 0 (or 0 < lhs). Proof: lhs rewritten as its
/// factored form (field), each factor times its sign at a point of the region positive (nra), their
/// product one factor at a time (Rmult_lt_0_compat), and lhs's sign from that product (nra).
std::string sign_lemma(const std::string& name, const proof_goal& g) {
  coq_printer p;
  const std::string left = p.term(g.lhs), factored = p.term(g.factored);
  std::vector<std::string> region;
  for (const ex& e : g.positive) region.push_back("0 < " + p.term(e));
  for (const ex& e : g.squares) p.term(e);  // their symbols are quantified over too
  std::vector<ex> factors;  // each times its sign at `inside`: positive on the region
  const auto add_factor = [&](const ex& f) {
    if (GiNaC::is_a<GiNaC::numeric>(f)) return;
    const ex at = GiNaC::normal(f.subs(g.inside));
    if (!GiNaC::is_a<GiNaC::numeric>(at) || at.is_zero()) throw unsupported("a factor without a sign at the region's point: " + p.term(f));
    factors.push_back(GiNaC::ex_to<GiNaC::numeric>(at).is_positive() ? f : ex(-f));
  };
  if (GiNaC::is_a<GiNaC::mul>(g.factored)) {
    for (std::size_t k = 0; k < g.factored.nops(); ++k) add_factor(g.factored.op(k));
  } else {
    add_factor(g.factored);
  }
  // Each factor positive (nra), then their product, one factor at a time (Rmult_lt_0_compat).
  std::vector<std::string> steps, squares;
  for (const ex& e : g.squares) squares.push_back("  assert (0 <= " + p.term(e) + " ^ 2) by apply pow2_ge_0.\n");
  // In the order of their text: GiNaC's order of a product's factors changes from run to run.
  std::vector<std::string> factor_texts;
  for (const ex& f : factors) factor_texts.push_back(p.term(f));
  std::sort(factor_texts.begin(), factor_texts.end());
  std::string product;
  for (const std::string& text : factor_texts) {
    // A denominator's inverse, (/ D): positive when D is (Rinv_0_lt_compat).
    const bool inverse = text.rfind("(/ ", 0) == 0;
    steps.push_back("  assert (0 < " + text + ") by " + (inverse ? "(apply Rinv_0_lt_compat; nra)" : "nra") + ".\n");
    if (!product.empty()) {
      product = "(" + product + " * " + text + ")";
      steps.push_back("  assert (0 < " + product + ") by (apply Rmult_lt_0_compat; assumption).\n");
    } else {
      product = text;
    }
  }
  std::string out = "Lemma " + name + " :" + premises_text(p);
  for (const std::string& r : region) out += "\n  " + r + " ->";
  out += "\n  " + (g.sign < 0 ? left + " < 0" : "0 < " + left) + ".\nProof.\n  intros.\n";
  if (factored != left) out += "  replace " + left + "\n    with " + factored + "\n    by (field; repeat split; nonzero).\n";
  for (const std::string& s : squares) out += s;
  for (const std::string& s : steps) out += s;
  return out + "  nra.\nQed.\n";
}

/// One lemma: lhs = rhs for scalars.
std::string lemma(const std::string& name, const coq_statement& s) {
  return "Lemma " + name + " :" + s.premises + "\n  " + s.left + "\n  = " + s.right +
         ".\nProof.\n  intros.\n  field; repeat split; nonzero.\nQed.\n";
}

/// `text` with each identifier in `values` replaced by its value: the statement at one point, as
/// Coq's instantiation of the quantifiers writes it.
std::string instantiated(const std::string& text, const std::map<std::string, std::string>& values) {
  std::string out;
  for (std::size_t k = 0; k < text.size();) {
    const auto identifier_char = [&](std::size_t at) { return std::isalnum(static_cast<unsigned char>(text[at])) || text[at] == '_'; };
    if (!identifier_char(k)) {
      out += text[k++];
      continue;
    }
    std::size_t end = k;
    while (end < text.size() && identifier_char(end)) ++end;
    const std::string token = text.substr(k, end - k);
    const auto it = values.find(token);
    out += it == values.end() ? token : it->second;
    k = end;
  }
  return out;
}

/// A point where the hypotheses hold (every symbol positive, every assumed denominator nonzero) and
/// lhs − rhs is a nonzero rational, with that difference; nullopt when none of the tried points is one.
std::optional<std::pair<GiNaC::exmap, GiNaC::numeric>> counterexample(const ex& lhs, const ex& rhs, const coq_statement& s) {
  static const int values[] = {2, 3, 5, 7, 11, 13, 17, 19, 23, 29};
  constexpr int count = sizeof values / sizeof values[0];
  for (int attempt = 0; attempt < 4 * count; ++attempt) {
    GiNaC::exmap point;
    int i = 0;
    for (const auto& [name, symbol] : s.symbols) point[symbol] = values[(i++ + attempt) % count] + attempt / count;
    try {
      bool premises_hold = true;
      for (const ex& e : s.nonzero) premises_hold = premises_hold && !GiNaC::normal(e.subs(point)).is_zero();
      const ex difference = GiNaC::normal((lhs - rhs).subs(point));
      if (premises_hold && GiNaC::is_a<GiNaC::numeric>(difference) && !difference.is_zero() &&
          GiNaC::ex_to<GiNaC::numeric>(difference).is_rational()) {
        return std::make_pair(point, GiNaC::ex_to<GiNaC::numeric>(difference));
      }
    } catch (const std::exception&) {  // a denominator vanishes at this point: try the next
    }
  }
  return std::nullopt;
}

/// The negation of lhs = rhs (with its hypotheses), shown at a counterexample point: both sides
/// there differ by a nonzero rational (field), yet the statement would make them equal.
std::optional<std::string> refutation_lemma(const std::string& name, const ex& lhs, const ex& rhs) {
  const coq_statement s = stated(lhs, rhs);
  const auto found = counterexample(lhs, rhs, s);
  if (!found) return std::nullopt;
  std::map<std::string, std::string> values;
  std::string arguments, where;
  for (const auto& [coq_name, symbol] : s.symbols) {
    const std::string value = "(" + coq_printer::number(GiNaC::ex_to<GiNaC::numeric>(found->first.at(symbol))) + ")";
    values[coq_name] = value;
    arguments += " " + value;
    where += (where.empty() ? "" : ", ") + coq_name + " = " + value;
  }
  const std::string left = instantiated(s.left, values), right = instantiated(s.right, values);
  const std::string difference = coq_printer::number(found->second);
  std::string out = "Lemma " + name + " :\n  ~ (" + s.premises.substr(s.premises.empty() ? 0 : 3) +
                    (s.premises.empty() ? "" : "\n  ") + s.left + "\n  = " + s.right + ").\n";
  out += "Proof.\n  intro H.\n";
  out += "  (* At " + (where.empty() ? std::string("this closed statement") : where) + " the two sides differ by " + difference + ". *)\n";
  out += "  assert (D : " + left + " - " + right + " = " + difference + ") by (field; premise).\n";
  out += "  assert (E : " + left + " = " + right + ") by (apply (H" + arguments + "); premise).\n";
  out += "  rewrite (Rminus_diag_eq _ _ E) in D.\n  lra.\nQed.\n";
  return out;
}

/// Letters, digits and '_' as they are; with `spell_signs`, '+' as p, '-' as m and '/' as over;
/// every other character '_'; "v_" before a leading digit.
std::string coq_name(const std::string& name, bool spell_signs) {
  std::string out;
  for (const char c : name) {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '_') {
      out += c;
    } else if (spell_signs && c == '+') {
      out += "p";  // q_j+1: q_jp1
    } else if (spell_signs && c == '-') {
      out += "m";  // q_j-1: q_jm1
    } else if (spell_signs && c == '/') {
      out += "over";  // q_j+1/2: q_jp1over2
    } else {
      out += '_';
    }
  }
  if (out.empty() || std::isdigit(static_cast<unsigned char>(out.front()))) out = "v_" + out;
  return out;
}

}  // namespace

std::string coq_identifier(const std::string& name) { return coq_name(name, false); }

std::string coq_symbol_identifier(const std::string& name) { return coq_name(name, true); }

namespace {

/// A comment's text: "(*" and "*)" inside it would end or nest it.
std::string comment_text(std::string said) {
  for (const std::string& token : {std::string("(*"), std::string("*)")}) {
    for (std::size_t at = said.find(token); at != std::string::npos; at = said.find(token, at)) said.replace(at, 2, token == "(*" ? "( *" : "* )");
  }
  return said;
}

/// The entries of an identity: one for scalars, one per entry (named _ij) for matrices.
std::vector<std::tuple<std::string, ex, ex>> entries(const std::string& base, const proof_goal& g) {
  const ex l = g.lhs.evalm(), r = g.rhs.evalm();
  if (GiNaC::is_a<GiNaC::matrix>(l) != GiNaC::is_a<GiNaC::matrix>(r)) throw unsupported("a matrix equated with a scalar");
  if (!GiNaC::is_a<GiNaC::matrix>(l)) return {{base, l, r}};
  const GiNaC::matrix& L = GiNaC::ex_to<GiNaC::matrix>(l);
  const GiNaC::matrix& R = GiNaC::ex_to<GiNaC::matrix>(r);
  if (L.rows() != R.rows() || L.cols() != R.cols()) throw unsupported("matrices of different shapes");
  std::vector<std::tuple<std::string, ex, ex>> out;
  for (unsigned i = 0; i < L.rows(); ++i) {
    for (unsigned j = 0; j < L.cols(); ++j) out.emplace_back(base + "_" + std::to_string(i + 1) + std::to_string(j + 1), L(i, j), R(i, j));
  }
  return out;
}

const char* const nonzero_tactic =
    "(* field leaves side conditions X <> 0 in its own normal form: each is a hypothesis up to ring,\n"
    "   a positive hypothesis, or a power of one. *)\n"
    "Ltac nonzero :=\n"
    "  first [ assumption\n"
    "        | match goal with\n"
    "          | [ H : ?Y <> 0 |- ?X <> 0 ] => replace X with Y by ring; exact H\n"
    "          | [ H : 0 < ?Y |- ?X <> 0 ] => replace X with Y by ring; apply Rgt_not_eq; exact H\n"
    "          end\n"
    "        | apply pow_nonzero; nonzero ].\n";

/// The refutations' tactic: a hypothesis at the counterexample point is a numeric fact.
const char* const premise_tactic =
    "(* At the counterexample point every hypothesis is a numeric fact (0 < 3, 24 + 2 ^ 2 * 3 ^ 2 <> 0). *)\n"
    "Ltac premise := first [ lra | nra ].\n";

}  // namespace

coq_export coq_certificate(const std::string& claim_id, const std::string& statement, const std::vector<proof_goal>& goals) {
  coq_export out;
  const std::string module = coq_identifier(claim_id);
  std::string body, refuted_body;
  std::vector<std::string> refuted, restated, unrefuted;
  std::map<std::string, int> uses;
  try {
    for (const proof_goal& g : goals) {
      std::string base = module + "_" + coq_identifier(g.name);
      const int seen = uses[base]++;
      if (seen > 0) base += "_" + std::to_string(seen + 1);  // a claim that checks two formulas: printed, printed_2
      if (g.sign != 0) {
        if (!g.holds) {
          unrefuted.push_back(g.name);  // a sign refuted by GiNaC at a point: no Coq negation written
          continue;
        }
        body += "\n" + sign_lemma(base, g);
        out.lemmas.push_back(base);
        continue;
      }
      if (!g.holds) {
        // The first entry that differs at a point where the hypotheses hold is the counterexample.
        std::optional<std::string> negation;
        for (const auto& [name, l, r] : entries(base, g)) {
          if (GiNaC::normal(l - r).is_zero()) continue;
          negation = refutation_lemma(name + "_refuted", l, r);
          if (negation) {
            refuted_body += "\n" + *negation;
            out.refutation_lemmas.push_back(name + "_refuted");
            break;
          }
        }
        (negation ? refuted : unrefuted).push_back(g.name);
        continue;
      }
      for (const auto& [name, l, r] : entries(base, g)) {
        const coq_statement s = stated(l, r);
        if (s.left == s.right) {
          restated.push_back(name);
          continue;
        }
        body += "\n" + lemma(name, s);
        out.lemmas.push_back(name);
      }
    }
  } catch (const unsupported& e) {
    out.lemmas.clear();
    out.refutation_lemmas.clear();
    out.not_exported = std::string("Coq's field tactic cannot state it: ") + e.what();
    return out;
  }
  const auto listed = [](const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
    return text;
  };
  const std::string header = "Require Import Reals Field Lra Psatz.\nOpen Scope R_scope.\n\n";
  const std::string said = comment_text(statement);
  if (!out.refutation_lemmas.empty()) {
    out.refutation = "(* Refutation of claim " + claim_id + " as printed: " + said +
                     "\n   The printed identity, for all values under its hypotheses, is false: each lemma is its negation,\n"
                     "   shown at one point where the two sides differ. Written by simpson-verify from the expressions\n"
                     "   its GiNaC kernel compared; check with coqc. *)\n" +
                     header + premise_tactic + refuted_body;
  }
  if (out.lemmas.empty()) {
    out.not_exported = !restated.empty() ? "each identity's two sides are one expression once GiNaC has evaluated them (" + listed(restated) +
                                               "): a lemma X = X would check nothing"
                       : !refuted.empty() ? "no identity holds: " + listed(refuted) + " refuted (its negation is exported)"
                                          : "no identity decided by GiNaC";
    return out;
  }
  out.text = "(* Certificate of claim " + claim_id + ": " + said +
             "\n   Written by simpson-verify from the expressions its GiNaC kernel proved; check with coqc. *)\n" + header + nonzero_tactic +
             (refuted.empty() ? "" : "(* Refuted by GiNaC, negated in the claim's _refuted.v: " + listed(refuted) + ". *)\n") +
             (unrefuted.empty() ? "" : "(* Refuted by GiNaC, not negated here (a sign, or no counterexample point among those tried): " + listed(unrefuted) + ". *)\n") +
             (restated.empty() ? "" : "(* Not stated: " + listed(restated) + ", whose two sides GiNaC evaluates to one expression (X = X checks nothing). *)\n") +
             body;
  return out;
}

void record_certificate(claim_result& result, const coq_export& certificate) {
  result.certificate = certificate.text;
  result.certificate_lemmas = certificate.lemmas;
  result.certificate_missing = certificate.not_exported;
  result.refutation = certificate.refutation;
  result.refutation_lemmas = certificate.refutation_lemmas;
}

}  // namespace simpson::verify::detail
