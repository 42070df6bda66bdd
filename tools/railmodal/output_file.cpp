// Output files written whole or not at all, all of a run's or none: what every railmodal program
// that writes a file (railmodal, railmodal-mpi) does with -o and --spectra.
#include "output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <utility>

#include "commands.hpp"

namespace railmodal::cli {

namespace {

// The format an output file's extension names ("" for none): the same words --format takes.
std::string extension_format(const std::string& output) {
  const size_t dot = output.rfind('.'), slash = output.find_last_of("/\\");
  if (output == "-" || dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = output.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == "html" || ext == "htm") return "html";
  if (ext == "csv" || ext == "json") return ext;
  if (ext == "md" || ext == "markdown") return "markdown";
  return "";
}

std::string listed(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& w : words) text += (text.empty() ? "" : ", ") + w;
  return text;
}

}  // namespace

OutputFormat report_format(const std::string& word, const std::string& output, const std::vector<std::string>& formats,
                           const std::string& writer) {
  if (!word.empty()) return *output_format_from_string(word);
  const std::string named = extension_format(output);
  if (named.empty()) return *output_format_from_string(formats.front());
  if (std::find(formats.begin(), formats.end(), named) == formats.end())
    throw UsageError("-o " + output + ": its extension asks for " + named + ", and " + writer + " writes " +
                     listed(formats) + ": give --format or another file name");
  return *output_format_from_string(named);
}

std::string format_rule_help(const std::vector<std::string>& formats) {
  return "default: what the -o file's extension names (.html, .csv, .json, .md), else " + formats.front();
}

namespace {

namespace fs = std::filesystem;

// Bytes to a file descriptor through a buffer: std::ofstream cannot write to the descriptor that
// mkstemp opened, and opening the temporary again by name could follow what replaced it.
class DescriptorBuffer : public std::streambuf {
 public:
  explicit DescriptorBuffer(int fd) : fd_(fd) { setp(buffer_, buffer_ + sizeof buffer_); }
  int error() const { return error_; }  ///< the errno of the first failed write, or 0

 protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  bool drain() {
    for (const char* p = pbase(); p < pptr();) {
      const ssize_t written = ::write(fd_, p, static_cast<size_t>(pptr() - p));
      if (written < 0 && errno == EINTR) continue;
      if (written <= 0) {
        error_ = written < 0 ? errno : EIO;
        return false;
      }
      p += written;
    }
    setp(buffer_, buffer_ + sizeof buffer_);
    return true;
  }

  int fd_;
  int error_ = 0;
  char buffer_[1 << 16];
};

std::string cannot_write(const std::string& path, const std::string& why) {
  return path + ": error: cannot write the output file: " + why;
}

// The permissions a file created by open() would have: mkstemp makes its file private (0600).
mode_t new_file_mode() {
  static const mode_t mask = [] {
    const mode_t m = ::umask(0);
    ::umask(m);
    return m;
  }();
  return 0666 & ~mask;
}

// A new file beside `target`, on its file system (so that rename replaces the target in one
// step), under a name no one can predict, created exclusively (mkstemp: O_CREAT | O_EXCL): a
// symlink or directory planted in the folder is never followed, written or removed.
int create_temporary(const std::string& target, std::string* temporary) {
  const fs::path path(target);
  // ".<name>.XXXXXX" stays within the 255 bytes a name may have on Linux and macOS.
  *temporary = (path.parent_path() / ("." + path.filename().string().substr(0, 200) + ".XXXXXX")).string();
  const int fd = ::mkstemp(temporary->data());
  if (fd < 0) {
    const std::string folder = path.parent_path().empty() ? "." : path.parent_path().string();
    throw OutputError(kOutput,
                      cannot_write(target, "cannot create a file in '" + folder + "': " + std::strerror(errno)));
  }
  ::fchmod(fd, new_file_mode());
  return fd;
}

// What two names of one file share: where their links lead (weakly: the file may not exist yet).
std::string resolved(const std::string& path) {
  std::error_code error;
  const fs::path canonical = fs::weakly_canonical(path, error);
  return error ? fs::absolute(path, error).lexically_normal().string() : canonical.string();
}

}  // namespace

struct OutputFiles::Output {
  std::string path;       ///< as the command line gave it; "-" for standard output
  std::string temporary;  ///< renamed to path by commit; "" when written in place
  std::string resolved;   ///< the path with its links followed, to tell two names of one file
  int fd = -1;            ///< the file or device, open until finished; -1 for standard output
  bool exists = false;    ///< the target existed when opened, as device and inode:
  dev_t device = 0;
  ino_t inode = 0;
  std::unique_ptr<DescriptorBuffer> buffer;
  std::unique_ptr<std::ostream> stream;

  bool standard_output() const { return path == "-"; }
  bool written_in_place() const { return !standard_output() && temporary.empty(); }  ///< a device, once opened
  std::ostream& out() { return standard_output() ? std::cout : *stream; }
  bool is(const Output& other) const {
    return resolved == other.resolved || (exists && other.exists && device == other.device && inode == other.inode);
  }
  // Written and flushed; throws OutputError otherwise. No fsync: it cost 10 ms per file (a
  // 14 ms `modes` run took 24.6 ms), and the guarantee users need is against a failed or killed
  // run, which the rename gives; surviving power loss is the file system's (ext4 flushes a file
  // renamed over another, auto_da_alloc).
  void finish() {
    if (standard_output()) {
      if (!std::cout.flush()) throw OutputError(kOutput, "railmodal: error: cannot write to standard output");
      return;
    }
    if (!stream->flush())
      throw OutputError(kOutput, cannot_write(path, std::strerror(buffer->error() ? buffer->error() : EIO)));
    if (::close(std::exchange(fd, -1)) != 0) throw OutputError(kOutput, cannot_write(path, std::strerror(errno)));
  }
};

OutputFiles::OutputFiles() = default;

OutputFiles::~OutputFiles() {
  for (const auto& output : outputs_) {
    if (output->fd >= 0) ::close(output->fd);
    if (!output->temporary.empty()) ::unlink(output->temporary.c_str());  // never a directory
  }
}

std::ostream& OutputFiles::open(const std::string& path) {
  auto output = std::make_unique<Output>();
  output->path = path.empty() ? "-" : path;
  output->resolved = output->standard_output() ? "-" : resolved(path);
  struct stat status;
  if (!output->standard_output() && ::stat(path.c_str(), &status) == 0) {
    if (S_ISDIR(status.st_mode)) throw OutputError(kOutput, cannot_write(path, "it is a directory"));
    output->exists = true;
    output->device = status.st_dev;
    output->inode = status.st_ino;
  }
  // A device may take several outputs (/dev/null), a file or standard output one.
  const bool device = output->exists && !S_ISREG(status.st_mode);
  for (const auto& earlier : outputs_)
    if (!device && !earlier->written_in_place() && output->is(*earlier))
      throw OutputError(kUsage, "railmodal: error: two outputs of this run are one file ('" + earlier->path +
                                    "' and '" + output->path + "'): each output needs a file of its own");
  if (!output->standard_output()) {
    // A device or pipe (/dev/null, a FIFO) is written as the run goes: renaming would replace it.
    output->fd = device ? ::open(path.c_str(), O_WRONLY | O_NOCTTY) : create_temporary(path, &output->temporary);
    if (output->fd < 0) throw OutputError(kOutput, cannot_write(path, std::strerror(errno)));
    output->buffer = std::make_unique<DescriptorBuffer>(output->fd);
    output->stream = std::make_unique<std::ostream>(output->buffer.get());
  }
  outputs_.push_back(std::move(output));
  return outputs_.back()->out();
}

void OutputFiles::refuse_inputs(const std::vector<std::string>& inputs) const {
  for (const std::string& input : inputs) {
    struct stat status;
    if (input.empty() || ::stat(input.c_str(), &status) != 0) continue;  // a missing input is the reader's error
    for (const auto& output : outputs_)
      if (output->exists && output->device == status.st_dev && output->inode == status.st_ino)
        throw OutputError(kUsage,
                          "railmodal: error: the output '" + output->path + "' is the input file '" + input +
                              "' of this run; railmodal does not write over its inputs: give another output file");
  }
}

void OutputFiles::commit() {
  // Every output whole on the disk before any is renamed: a failure leaves every target as it was.
  for (const auto& output : outputs_) output->finish();
  for (const auto& output : outputs_) {
    if (output->temporary.empty()) continue;
    if (::rename(output->temporary.c_str(), output->path.c_str()) != 0)
      throw OutputError(kOutput, cannot_write(output->path, std::strerror(errno)));
    output->temporary.clear();
  }
}

}  // namespace railmodal::cli
