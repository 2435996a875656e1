#pragma once
// Private to renderer/: the numeric rows of a data file compiled into the program (spectra,
// band responses): lines split on commas, tabs or spaces; blank lines, lines starting with
// '#' and a first line that is not numeric (a header) are skipped. The embedded files are
// ours and fixed, so a malformed one is a programming error (std::logic_error naming it).
#include <string_view>
#include <vector>

namespace landsim::renderer::detail {

std::vector<std::vector<double>> number_rows(std::string_view text, const char* name);

}  // namespace landsim::renderer::detail
