/// @file `linear --symbolic` in the report: Φ(t) as the solution x(t) = Φ(t) x(0) written
/// out row by row, and G(s) for each --transfer pair, as text and as a JSON member.
#pragma once

#include <string>

#include "studies/linear_report.hpp"

namespace eomgen::studies {

void print_closed_form_text(const LinearReport& r);

/// ", \"symbolic\": {...}" when the report has a closed form, else empty.
std::string closed_form_json(const LinearReport& r);

}  // namespace eomgen::studies
