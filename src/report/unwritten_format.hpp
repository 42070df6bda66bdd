// The message of a writer asked for a format it does not write.
#pragma once

#include <string>

#include "railmodal/output_format.hpp"

namespace railmodal::report {

/// "write_modes writes table, csv or json, not html": `writer` names the function, `written`
/// the formats it writes.
std::string unwritten_format(const std::string& writer, const std::string& written, OutputFormat format);

}  // namespace railmodal::report
