// The temporary file of texts: appended under a lock, read back one text a read, or front to back.
#include "study/spilled_texts.hpp"

#include <stdlib.h>  // mkstemp
#include <unistd.h>  // unlink, pread

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
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

void SpilledTexts::resize(size_t count) { offsets_.resize(count), lengths_.resize(count), put_order_.reserve(count); }

void SpilledTexts::put(size_t position, const std::string& text) {
  const std::lock_guard<std::mutex> lock(mutex_);
  failed_ = failed_ || std::fwrite(text.data(), 1, text.size(), file_.get()) != text.size();
  offsets_.at(position) = written_;
  lengths_.at(position) = static_cast<unsigned>(text.size());
  written_ += text.size();
  put_order_.push_back(position);
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
  // buffered read were two system calls and a 4 KiB refill per text.
  read(text.data(), text.size(), offsets_[position]);
  return text;
}

void SpilledTexts::read(char* to, size_t bytes, unsigned long long offset) const {
  const int fd = fileno(file_.get());
  size_t done = 0;
  while (done < bytes) {
    const ssize_t got = pread(fd, to + done, bytes - done, static_cast<off_t>(offset + done));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0)
      throw std::system_error(got < 0 ? errno : EIO, std::generic_category(),
                              purpose_ + " but could not read back its temporary file");
    done += static_cast<size_t>(got);
  }
}

void SpilledTexts::each_of(const std::vector<size_t>& positions, const std::function<void(std::string_view)>& visit,
                           size_t gather_bytes) const {
  // Every position checked before any text is visited: a bad request writes nothing.
  unsigned long long wanted = 0;
  std::vector<bool> asked(offsets_.size(), false);
  for (size_t p : positions) {
    if (p >= offsets_.size())
      throw std::out_of_range("no text at position " + std::to_string(p) + " of " + std::to_string(size()));
    if (asked[p]) throw std::invalid_argument("each_of: position " + std::to_string(p) + " is asked for twice");
    asked[p] = true;
    wanted += lengths_[p];
  }
  // Each pass reads the whole file; one read a text costs a system call, about what copying a
  // page does (kCallBytes). The rows of a study are read in rank order, scattered over the file:
  // one pread a text was most of the serial part of the 10^5-variant study (docs/performance.md,
  // "study-serial"). Many short texts are gathered in passes; texts of kilobytes each (a shard's
  // JSON), a few texts of a large file or a file many times the gathering room, one read a text.
  constexpr unsigned long long kCallBytes = 4096;
  const unsigned long long passes = gather_bytes > 0 ? (wanted + gather_bytes - 1) / gather_bytes : positions.size();
  if (passes * written_ > positions.size() * kCallBytes + wanted) {
    for (size_t p : positions) visit(at(p));
    return;
  }
  constexpr size_t kNone = SIZE_MAX;
  constexpr size_t kChunkBytes = size_t{1} << 20;
  std::vector<size_t> slot(offsets_.size(), kNone);  // where a text of this pass goes in `block`
  std::string block;
  std::vector<char> chunk(static_cast<size_t>(std::min<unsigned long long>(kChunkBytes, written_)));
  for (size_t first = 0; first < positions.size();) {
    // The texts of positions[first ... last − 1]: as many as fit in gather_bytes, at least one.
    size_t bytes = 0, last = first;
    for (; last < positions.size() && (last == first || bytes + lengths_[positions[last]] <= gather_bytes); ++last) {
      slot[positions[last]] = bytes;
      bytes += lengths_[positions[last]];
    }
    block.resize(bytes);
    // The file front to back, a chunk at a time: its texts lie in the order they were put.
    unsigned long long chunk_at = 0, chunk_end = 0;
    for (size_t p : put_order_) {
      if (slot[p] == kNone) continue;
      unsigned long long from = offsets_[p];
      size_t left = lengths_[p];
      char* to = block.data() + slot[p];
      while (left > 0) {
        if (from < chunk_at || from >= chunk_end) {
          chunk_at = from;
          chunk_end = from + std::min<unsigned long long>(chunk.size(), written_ - from);
          read(chunk.data(), static_cast<size_t>(chunk_end - chunk_at), chunk_at);
        }
        const size_t piece = static_cast<size_t>(std::min<unsigned long long>(left, chunk_end - from));
        std::memcpy(to, chunk.data() + (from - chunk_at), piece);
        to += piece, from += piece, left -= piece;
      }
    }
    for (; first < last; ++first) {
      const size_t p = positions[first];
      visit(std::string_view(block.data() + slot[p], lengths_[p]));
      slot[p] = kNone;
    }
  }
}

}  // namespace railmodal::study
