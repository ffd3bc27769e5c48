#pragma once
// SHA-256 digests (OpenSSL's EVP interface) for the reproducibility record of a report: the scene
// and the paper a run read.

#include <string>

namespace simpson::verify {

/// The SHA-256 of `bytes` as 64 lower-case hex digits.
std::string sha256_hex(const std::string& bytes);

}  // namespace simpson::verify
