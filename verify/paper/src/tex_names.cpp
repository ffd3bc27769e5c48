// The names the reader gives (symbols, functions, derivatives, Greek letters, subscripts) and the
// held det and tr: see tex_math.hpp and tex_math_parts.hpp.

#include <simpson/verify/tex_math.hpp>

#include "tex_math_parts.hpp"

#include <simpson/verify/tex_macros.hpp>

#include <algorithm>
#include <cctype>
#include <optional>

namespace simpson::verify {

const GiNaC::symbol& tex_symbols::operator[](const std::string& name) {
  auto it = symbols_.find(name);
  if (it == symbols_.end()) it = symbols_.emplace(name, GiNaC::symbol(name)).first;
  return it->second;
}

tex_symbols& paper_symbols() {
  static tex_symbols symbols;
  return symbols;
}

const std::map<std::string, std::string>& reserved_names() {
  static const std::map<std::string, std::string> names{
      {"O", "O(...) is Landau's symbol"}, {"pi", "\\pi is the constant"}};
  return names;
}

namespace {

/// The GiNaC serial of each function the reader registered, by name and arity (a cache of GiNaC's
/// own registry, which is process-wide by GiNaC's design).
std::map<std::pair<std::string, std::size_t>, unsigned>& registered_functions() {
  static std::map<std::pair<std::string, std::size_t>, unsigned> serials;
  return serials;
}

}  // namespace

std::string function_name(const std::string& name, std::size_t arity) {
  // One of GiNaC's own (psi, the digamma function; beta; zeta): ours is registered apart under a
  // marked name, so that GiNaC never evaluates it as its own. Decided once, before ours exists.
  static std::map<std::pair<std::string, std::size_t>, std::string> names;
  const auto key = std::make_pair(name, arity);
  const auto it = names.find(key);
  if (it != names.end()) return it->second;
  std::string registered = name + "_f";
  try {
    (void)GiNaC::function::find_function(name, static_cast<unsigned>(arity));
  } catch (const std::runtime_error&) {
    registered = name;
  }
  return names.emplace(key, registered).first->second;
}

GiNaC::ex apply_function(const std::string& name, const GiNaC::exvector& args) {
  auto& serials = registered_functions();
  const auto key = std::make_pair(name, args.size());
  auto it = serials.find(key);
  if (it == serials.end()) {
    const std::string registered = function_name(name, args.size());
    it = serials.emplace(key, GiNaC::function::register_new(GiNaC::function_options(registered, static_cast<unsigned>(args.size())))).first;
  }
  return GiNaC::function(it->second, args);
}

bool is_reader_function(const GiNaC::ex& e) {
  if (!GiNaC::is_a<GiNaC::function>(e)) return false;
  const unsigned serial = GiNaC::ex_to<GiNaC::function>(e).get_serial();
  for (const auto& [key, registered] : registered_functions()) {
    if (registered == serial) return key.first != "sum";
  }
  return false;
}

std::string derivative_name(const std::string& of, const std::string& by, int k, int n) {
  const auto power = [](int e) { return e == 1 ? std::string() : "^" + std::to_string(e); };
  return "d" + power(k) + of + "/d" + by + power(n);
}

GiNaC::ex jacobian_of(const std::vector<GiNaC::symbol>& to, const std::vector<GiNaC::symbol>& from) {
  GiNaC::lst above, below;
  for (const GiNaC::symbol& s : to) above.append(s);
  for (const GiNaC::symbol& s : from) below.append(s);
  return GiNaC::function(tex_reading::jacobian_serial(), above, below).hold();
}

bool is_jacobian(const GiNaC::ex& e) {
  return GiNaC::is_exactly_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_serial() == tex_reading::jacobian_serial();
}

std::pair<std::vector<GiNaC::symbol>, std::vector<GiNaC::symbol>> jacobian_names(const GiNaC::ex& e) {
  std::pair<std::vector<GiNaC::symbol>, std::vector<GiNaC::symbol>> out;
  for (const GiNaC::ex& s : e.op(0)) out.first.push_back(GiNaC::ex_to<GiNaC::symbol>(s));
  for (const GiNaC::ex& s : e.op(1)) out.second.push_back(GiNaC::ex_to<GiNaC::symbol>(s));
  return out;
}

bool is_sum(const GiNaC::ex& e) {
  return GiNaC::is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_name() == "sum" && e.nops() == 4;
}

// det and tr of a named matrix: held until the matrix is put in, then evaluated.
namespace tex_reading {

GiNaC::ex det_eval(const GiNaC::ex& x) {
  const GiNaC::ex m = GiNaC::is_a<GiNaC::matrix>(x) ? x : x.evalm();
  if (GiNaC::is_a<GiNaC::matrix>(m) && GiNaC::ex_to<GiNaC::matrix>(m).rows() == GiNaC::ex_to<GiNaC::matrix>(m).cols()) {
    return GiNaC::ex_to<GiNaC::matrix>(m).determinant();
  }
  return GiNaC::function(GiNaC::function::find_function("det", 1), x).hold();
}

GiNaC::ex trace_eval(const GiNaC::ex& x) {
  const GiNaC::ex m = GiNaC::is_a<GiNaC::matrix>(x) ? x : x.evalm();
  if (GiNaC::is_a<GiNaC::matrix>(m) && GiNaC::ex_to<GiNaC::matrix>(m).rows() == GiNaC::ex_to<GiNaC::matrix>(m).cols()) {
    return GiNaC::ex_to<GiNaC::matrix>(m).trace();
  }
  return GiNaC::function(GiNaC::function::find_function("tr", 1), x).hold();
}

unsigned det_serial() {
  static const unsigned serial = GiNaC::function::register_new(GiNaC::function_options("det", 1).eval_func(det_eval).latex_name("\\det"));
  return serial;
}

unsigned trace_serial() {
  static const unsigned serial = GiNaC::function::register_new(GiNaC::function_options("tr", 1).eval_func(trace_eval).latex_name("\\operatorname{tr}"));
  return serial;
}

GiNaC::ex determinant_of(const GiNaC::ex& x) { return GiNaC::function(det_serial(), x); }

unsigned jacobian_serial() {
  static const unsigned serial = GiNaC::function::register_new(GiNaC::function_options("jacobian", 2));
  return serial;
}
GiNaC::ex trace_of(const GiNaC::ex& x) { return GiNaC::function(trace_serial(), x); }

// --- names

const tex_node& unwrapped(const tex_node& n) {  // {x} is x
  if (n.kind == tex_node_kind::group && n.children.size() == 1) return unwrapped(n.children.front());
  return n;
}

tex_list unwrapped_list(const tex_list& list) {  // {{a b}} is a b
  if (list.size() == 1 && list.front().kind == tex_node_kind::group) return unwrapped_list(list.front().children);
  return list;
}

void refuse(const std::string& why, const tex_node& n, const std::string& hint) {
  throw tex_error(why, n.offset, n.text, hint);
}

std::string greek_name(const std::string& command) {
  if (command == "\\ell") return "l";
  return command.substr(1);
}

bool is_greek_or_letter(const tex_node& n) {
  if (n.kind != tex_node_kind::atom) return false;
  if (n.text.size() == 1) return std::isalpha(static_cast<unsigned char>(n.text[0])) != 0;
  static const std::set<std::string> letters{"\\alpha", "\\beta",  "\\gamma", "\\delta", "\\epsilon", "\\varepsilon", "\\zeta", "\\eta",
                                             "\\theta", "\\vartheta", "\\iota", "\\kappa", "\\lambda", "\\mu",     "\\nu",   "\\xi",
                                             "\\varpi", "\\rho",   "\\varrho", "\\sigma", "\\varsigma", "\\tau", "\\upsilon", "\\phi",
                                             "\\varphi", "\\chi",  "\\psi",   "\\omega", "\\Gamma", "\\Delta",   "\\Theta", "\\Lambda",
                                             "\\Xi",    "\\Pi",    "\\Sigma", "\\Upsilon", "\\Phi", "\\Psi",     "\\Omega", "\\ell", "\\hbar"};
  return letters.count(n.text) > 0;
}

/// The text of a subscript: q_{j+1} is "j+1", q_\ell "l", t_{\rm end} "end".
std::string subscript_text(const tex_node& n) {
  switch (n.kind) {
    case tex_node_kind::atom:
      if (n.text.size() > 1 && n.text[0] == '\\') {
        if (is_greek_or_letter(n)) return greek_name(n.text);
        refuse("the symbol " + n.text + " in a subscript", n);
      }
      return n.text;
    case tex_node_kind::group:
    case tex_node_kind::font: {
      std::string out;
      for (const tex_node& c : n.children) out += subscript_text(c);
      return out;
    }
    case tex_node_kind::scripts:
      if (!n.sup.empty()) refuse("a superscript inside a subscript", n);
      return subscript_text(n.children.front()) + "_" + subscript_text(n.sub.front());
    case tex_node_kind::label: return "";
    case tex_node_kind::fraction: {  // q_{j+\frac12}: the half-index node q_{j+1/2}
      const auto digits = [](const tex_node& part) -> std::optional<std::string> {
        std::string out;
        for (const tex_node& c : unwrapped_list(part.children)) {
          if (c.kind != tex_node_kind::atom || c.text.size() != 1 || !std::isdigit(static_cast<unsigned char>(c.text[0]))) return std::nullopt;
          out += c.text;
        }
        return out.empty() ? std::nullopt : std::optional<std::string>(out);
      };
      if (n.text != "\\frac" && n.text != "\\tfrac" && n.text != "\\dfrac") break;
      const auto top = digits(n.children[0]), bottom = digits(n.children[1]);
      if (top && bottom) return *top + "/" + *bottom;
      break;
    }
    default: break;
  }
  refuse("a subscript that is not a name nor an index (a fraction, a root, ...)", n);
}

std::optional<std::string> font_letters(const tex_node& n) {  // \mathrm{tr}: "tr"
  if (n.kind != tex_node_kind::font) return std::nullopt;
  const tex_list& letters = n.children.size() == 1 && n.children.front().kind == tex_node_kind::group ? n.children.front().children : n.children;
  std::string out;
  for (const tex_node& c : letters) {
    const tex_node& u = unwrapped(c);
    if (u.kind != tex_node_kind::atom || u.text.size() != 1 || !std::isalpha(static_cast<unsigned char>(u.text[0]))) return std::nullopt;
    out += u.text;
  }
  return out;
}

/// The upright letters of {\rm det}, \mathrm{tr}, \operatorname{tr}, \mathcal O: the font and its
/// letters, when the node (or the group it is alone in) is that.
std::optional<std::pair<std::string, std::string>> upright(const tex_node& given) {
  const tex_node& n = unwrapped(given);
  if (n.kind != tex_node_kind::font) return std::nullopt;
  const std::optional<std::string> letters = font_letters(n);
  if (!letters) return std::nullopt;
  return std::make_pair(n.text, *letters);
}

}  // namespace tex_reading

using namespace tex_reading;

std::string symbol_name(const tex_node& given) {
  const tex_node& n = unwrapped(given);
  if (is_greek_or_letter(n)) return n.text.size() == 1 ? n.text : greek_name(n.text);
  if (n.kind == tex_node_kind::scripts && n.sup.empty() && !n.sub.empty()) return symbol_name(n.children.front()) + "_" + subscript_text(n.sub.front());
  if (n.kind == tex_node_kind::accent) {
    const std::string base = symbol_name(n.children.front());
    if (n.text == "\\dot") return derivative_name(base, "t", 1, 1);
    if (n.text == "\\ddot") return derivative_name(base, "t", 2, 2);
    if (n.text == "\\dddot") return derivative_name(base, "t", 3, 3);
    return n.text.substr(1) + "(" + base + ")";
  }
  if (n.kind == tex_node_kind::font && (n.text == "mathbf" || n.text == "boldsymbol" || n.text == "mathcal" || n.text == "mathbb")) {
    if (n.children.size() == 1 && is_greek_or_letter(unwrapped(n.children.front()))) {
      return std::string(n.text == "mathcal" ? "cal" : n.text == "mathbb" ? "bb" : "bold") + "(" + symbol_name(n.children.front()) + ")";
    }
  }
  refuse("not one name", n);
}

namespace tex_reading {

std::optional<differential> differential_of(const tex_node& given) {
  const tex_node& n = unwrapped(given);
  if (n.kind == tex_node_kind::scripts && n.sub.empty() && !n.sup.empty()) {
    std::optional<differential> d = differential_of(n.children.front());
    const tex_node& sup = unwrapped(n.sup.front());
    if (!d || sup.kind != tex_node_kind::atom || sup.text.size() != 1 || !std::isdigit(static_cast<unsigned char>(sup.text[0]))) return std::nullopt;
    d->order = sup.text[0] - '0';
    return d;
  }
  if (n.kind == tex_node_kind::atom && n.text == "d") return differential{false, true, 1};
  if (n.kind == tex_node_kind::atom && n.text == "\\partial") return differential{true, false, 1};
  if (const auto u = upright(n); u && u->second == "d" && (u->first == "mathrm" || u->first == "operatorname")) return differential{false, false, 1};
  return std::nullopt;
}

}  // namespace tex_reading

}  // namespace simpson::verify
