// The output files of one run of railmodal or railmodal-mpi (docs/input.md, "Output files").
#pragma once

#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "railmodal/output_format.hpp"

namespace railmodal::cli {

/// A report's format, by one rule for every command (README.md, "Output formats"): `word`
/// (--format, checked by CLI11 against `formats`) when given; else the format the -o file's
/// extension names (.html or .htm, .csv, .json, .md or .markdown), which must be one of
/// `formats` (else a UsageError: ".html" never gets a text table); else `formats.front()`, the
/// command's default (standard output, no extension or another one such as .txt).
/// `writer` names what writes the report in that error ("a shard").
OutputFormat report_format(const std::string& word, const std::string& output, const std::vector<std::string>& formats,
                           const std::string& writer = "this command");

/// The end of every --format help: the rule above, with the command's default.
std::string format_rule_help(const std::vector<std::string>& formats);

/// An output that cannot be written (exit code kOutput) or that the command line names wrongly,
/// such as an input of the run (kUsage). main() prints the message and exits with the code.
class OutputError : public std::runtime_error {
 public:
  OutputError(int code, const std::string& message) : std::runtime_error(message), code_(code) {}
  int code() const { return code_; }

 private:
  int code_;
};

/// The outputs of one run, written whole or not at all, and all of them or none:
///
///     OutputFiles outputs;
///     std::ostream& out = outputs.open(o.output);      // before the analysis: a bad path fails now
///     outputs.refuse_inputs({o.file});                 // railmodal does not write over its inputs
///     write_modes(out, system.vehicle.name, solve_modes(system, options), format);
///     outputs.commit();                                // every file appears, or none
///
/// A file is written into a temporary beside it (a new name, created exclusively: nothing
/// planted in the directory is followed or removed) and renamed into place by commit() once
/// every output of the run has been written. Without commit (an error, an exception) the
/// temporaries are removed and the targets are untouched. "-" or "" is standard output, and a
/// device or pipe (/dev/null, a FIFO) is written as the run goes: neither can be replaced whole.
/// Every function throws OutputError.
class OutputFiles {
 public:
  OutputFiles();
  ~OutputFiles();
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;

  /// The stream for `path`, valid until commit or destruction. Refuses (kOutput) a directory or
  /// a path whose directory does not exist or cannot be written, and (kUsage) a path that is
  /// already an output of this run.
  std::ostream& open(const std::string& path);
  /// Refuses (kUsage) an output that is one of these files ("" is skipped): the same file by
  /// device and inode, through whatever links.
  void refuse_inputs(const std::vector<std::string>& inputs) const;
  /// Flushes every output and, when all were written, renames the files into place.
  void commit();

 private:
  struct Output;
  std::vector<std::unique_ptr<Output>> outputs_;
};

}  // namespace railmodal::cli
