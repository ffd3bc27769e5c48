#pragma once
// report.junit.xml: the run in the JUnit XML that the GitLab, Jenkins and GitHub test reporters
// read. One testsuite "claims" with a testcase per claim, failed when the verdict differs from the
// expected one; one testsuite per experiment section with a testcase per table, failed when a cell
// holds a fault (overflow, underflow, non-finite, unstable, failed).

#include <simpson/verify/run.hpp>

#include <string>

namespace simpson::verify {

std::string report_junit(const run_record& r);

}  // namespace simpson::verify
