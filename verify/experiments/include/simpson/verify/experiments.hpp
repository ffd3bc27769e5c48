#pragma once
// Every experiment section's header, for the code that runs a section by its own function (the
// tests, the book's published facts). The app does not include it: it iterates the registry of
// sections (experiment_section.hpp; the book's experiment_sections()).

#include <simpson/verify/experiment_section.hpp>
#include <simpson/verify/family_section.hpp>
#include <simpson/verify/floating_section.hpp>
#include <simpson/verify/fpu_section.hpp>
#include <simpson/verify/inseparable_section.hpp>
#include <simpson/verify/long_time_section.hpp>
#include <simpson/verify/nonlinear_section.hpp>
#include <simpson/verify/stability_section.hpp>
#include <simpson/verify/table1_section.hpp>
#include <simpson/verify/work_precision_section.hpp>
