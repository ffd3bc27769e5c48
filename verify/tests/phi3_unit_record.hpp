#pragma once
// One claims-file record of the tests: det Phi_3 = 1 on the paper's (Phi3), a determinant shape.
// A test appends a field to it (core = ..., correction = ...) and reads the result as a book.

#include <string>

namespace simpson::verify {

inline const std::string phi3_unit_record = R"([[claim]]
id = "phi3-unit"
section = "6"
equation = 'Phi3'
statement = 'det Phi_3 = 1.'
methods = ["exact"]
shape = "determinant"
with = { matrix = "Phi3", equals = "inline:It is easy with SageMath to verify that" }
)";

}  // namespace simpson::verify
