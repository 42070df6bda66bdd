// railmodal — the formats a report is written in, one enum for every writer.
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     auto system = railmodal::assemble(railmodal::load_vehicle("data/vehicles/fette_car.toml"), railmodal::DofSet::all);
//     auto result = railmodal::solve_modes(system);
//     std::optional<railmodal::OutputFormat> format = railmodal::output_format_from_string("json");
//     if (!format) return 1;
//     railmodal::write_modes(std::cout, system, result, *format);  // table, csv or json
//   }
#pragma once

#include <optional>
#include <string>

namespace railmodal {

/// table: plain text for people; csv and json: for programs; markdown and html: documents to
/// read or hand in (HTML self-contained, plots as inline SVG). Each writer names the formats it
/// writes and throws std::invalid_argument naming itself and the format for any other.
enum class OutputFormat { table, csv, json, markdown, html };

/// "table", "csv", "json", "markdown" or "html".
const char* to_string(OutputFormat format);
/// The format to_string names `word`, or nothing.
std::optional<OutputFormat> output_format_from_string(const std::string& word);

}  // namespace railmodal
