#pragma once
// The validation report as one HTML file that needs no network: pictures as
// embedded PNGs, the chart as inline SVG.
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "validate/runs/validation.h"

namespace sandpic {

std::string base64(const std::vector<unsigned char>& bytes);
// Text for HTML (& < > " escaped); a number printed with fmt, "–" when not
// finite. Shared by the validation and verify-dem reports.
std::string html_escape(const std::string& s);
std::string html_number(const char* fmt, double v);
// Error (silhouette) against simulate time, log time axis, one point per run.
std::string error_time_svg(const Validation& v);
std::string validation_html(const Validation& v, const std::string& reproduce);

}  // namespace sandpic
