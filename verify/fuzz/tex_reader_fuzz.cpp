// libFuzzer target: the TeX reader must turn any document into its math (every row's tree, every
// side read) or a refusal that is bad input (std::invalid_argument: tex_error, a document that does
// not read), never crash, hang, leak or throw anything else (a harness fault, exit 3).

#include <simpson/verify/formula_reference.hpp>
#include <simpson/verify/paper_source.hpp>
#include <simpson/verify/tex_document.hpp>
#include <simpson/verify/tex_math.hpp>

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace simpson::verify;
  const std::string text(reinterpret_cast<const char*>(data), size);
  // A few names of each kind: a function, a state, symbols (and d, which makes d/dx ambiguous).
  static const tex_declarations declared{{"V", "q", "f", "L", "L_d"}, {"q", "x", "h", "m", "omega", "d", "t"}, {{"L", {"q", "dq/dt"}}, {"L_d", {"a", "b"}}}};
  try {
    const tex_document document = read_document(paper_source{"fuzz", without_comments(text), "", text});
    for (const tex_region& region : document.regions()) {
      try {
        for (const tex_equation& e : equations_of(region)) {
          for (const tex_list& side : e.sides) {
            try {
              (void)read_math(side, declared, paper_symbols());
            } catch (const tex_error&) {
            }
          }
        }
      } catch (const tex_error&) {
      }
    }
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
