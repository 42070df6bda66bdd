// The temporary file of texts: appended under a lock, read back with a seek.
#include "study/spilled_texts.hpp"

#include <stdlib.h>  // mkstemp
#include <unistd.h>  // unlink, pread

#include <cerrno>
#include <cstdlib>
#include <stdexcept>
#include <system_error>
#include <utility>

namespace railmodal::study {
namespace {

// The directory for the texts: TMPDIR, as other programs use it, or /tmp.
std::string temporary_directory() {
  const char* dir = std::getenv("TMPDIR");
  return dir && *dir ? dir : "/tmp";
}

// A file in `directory` that no other process sees and that goes when it is closed (or the
// process ends): unlinked as soon as it is open.
std::FILE* anonymous_file(const std::string& directory) {
  std::string path = directory + "/railmodal-ranking-XXXXXX";
  const int fd = mkstemp(path.data());
  if (fd < 0) return nullptr;
  unlink(path.c_str());
  std::FILE* file = fdopen(fd, "w+b");
  if (!file) close(fd);
  return file;
}

}  // namespace

SpilledTexts::SpilledTexts(std::string purpose, std::string remedy)
    : purpose_(std::move(purpose)), remedy_(std::move(remedy)), file_(anonymous_file(temporary_directory())) {
  if (!file_)
    throw std::system_error(errno, std::generic_category(),
                            purpose_ + " in a temporary file, and none could be opened in " + temporary_directory() +
                                " (set TMPDIR to a writable directory" + remedy_ + ")");
}

void SpilledTexts::resize(size_t count) { offsets_.resize(count), lengths_.resize(count); }

void SpilledTexts::put(size_t position, const std::string& text) {
  const std::lock_guard<std::mutex> lock(mutex_);
  failed_ = failed_ || std::fwrite(text.data(), 1, text.size(), file_.get()) != text.size();
  offsets_.at(position) = written_;
  lengths_.at(position) = static_cast<unsigned>(text.size());
  written_ += text.size();
}

void SpilledTexts::finish() {
  // A full disk shows at the write or only at the flush: both before a byte of the output.
  if (!failed_) failed_ = std::fflush(file_.get()) != 0 || std::ferror(file_.get()) != 0;
  if (failed_)
    throw std::system_error(errno ? errno : EIO, std::generic_category(),
                            purpose_ + " but could not write its temporary file in " + temporary_directory() +
                                " (free space there, set TMPDIR" + remedy_ + ")");
}

std::string SpilledTexts::at(size_t position) const {
  if (position >= offsets_.size())
    throw std::out_of_range("no text at position " + std::to_string(position) + " of " + std::to_string(size()));
  std::string text(lengths_[position], '\0');
  // One pread of the text's bytes from the flushed file (finish() came first): a seek and a
  // buffered read were two system calls and a 4 KiB refill per text, one text per variant of a
  // study, in the serial part that writes the ranked rows.
  const int fd = fileno(file_.get());
  size_t done = 0;
  while (done < text.size()) {
    const ssize_t got =
        pread(fd, text.data() + done, text.size() - done, static_cast<off_t>(offsets_[position] + done));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0)
      throw std::system_error(got < 0 ? errno : EIO, std::generic_category(),
                              purpose_ + " but could not read back its temporary file");
    done += static_cast<size_t>(got);
  }
  return text;
}

}  // namespace railmodal::study
