#pragma once
// report.junit.xml: the run in the JUnit XML that the GitLab, Jenkins and GitHub test reporters
// read. Its failures and errors are exactly what makes the exit code non-zero (run_exit_code):
// - testsuite "claims", a testcase per claim with properties verdict and expected: a failure when
//   the verdict differs from the expected one or coqc rejected its certificate, an error when its
//   check threw; an erratum as expected passes with the printed and corrected text in <system-out>;
//   a `fails` as expected is <skipped> with its reason (an expected failure);
// - a testsuite per experiment section, a testcase per table: its faults (overflow, underflow,
//   non-finite, unstable) are findings, counted in a property and listed in <system-out>.

#include <simpson/verify/run.hpp>
#include <simpson/verify/verdict_table.hpp>

#include <string>

namespace simpson::verify {

std::string report_junit(const run_record& r);

}  // namespace simpson::verify
