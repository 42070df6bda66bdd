// Texts made out of order (one a variant, by the threads that evaluate them) and read back in
// any order later, kept in a temporary file: in memory only where each lies (12 bytes a text).
// A streamed ranking keeps its rows here until the ranking is known; a shard its results until
// they can be written in study order (issue 19, item 2).
#pragma once

#include <cstddef>
#include <cstdio>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

namespace railmodal::study {

class SpilledTexts {
 public:
  /// Opens the file in TMPDIR (or /tmp) and unlinks it at once: it goes when this does. Throws
  /// std::system_error if none can be opened, the message starting with `purpose` ("the
  /// ranking of a whole study keeps its rows") and ending with `remedy` (after "set TMPDIR to a
  /// writable directory").
  SpilledTexts(std::string purpose, std::string remedy);

  /// Room for `count` texts (positions 0 ... count − 1), before any is put.
  void resize(size_t count);
  /// Writes the text of `position`; several threads may put at once. A failed write is
  /// remembered and thrown by finish().
  void put(size_t position, const std::string& text);
  /// Flushes the file; throws std::system_error if a write failed (a full disk, say).
  void finish();
  /// The text put at `position`, once finish() has flushed the file; std::system_error if it
  /// cannot be read back.
  std::string at(size_t position) const;
  /// The texts at `positions` (each at most once: a repeated or missing position throws before
  /// any text is visited), handed to `visit` in that order, once finish() has flushed the file;
  /// each view lives until `visit` returns. Where reading the whole file costs less than one
  /// read a text (many short texts, the file not many times `gather_bytes`) it is read front to
  /// back, in passes that each gather the texts of as many consecutive entries as fit in
  /// `gather_bytes`; otherwise one read a text.
  void each_of(const std::vector<size_t>& positions, const std::function<void(std::string_view)>& visit,
               size_t gather_bytes = kGatherBytes) const;
  size_t size() const { return offsets_.size(); }

  /// What each_of gathers in memory at a time: the CSV rows of 10^5 variants (30 MB) in one pass.
  static constexpr size_t kGatherBytes = size_t{32} << 20;

 private:
  struct Closer {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  std::string purpose_, remedy_;
  std::unique_ptr<std::FILE, Closer> file_;
  std::mutex mutex_;
  unsigned long long written_ = 0;
  bool failed_ = false;
  std::vector<unsigned long long> offsets_;  ///< where each text starts
  std::vector<unsigned> lengths_;            ///< its length
  std::vector<size_t> put_order_;            ///< the positions in the order put: the file's order
  /// Reads `bytes` bytes of the file at `offset` into `to`; throws std::system_error if it cannot.
  void read(char* to, size_t bytes, unsigned long long offset) const;
};

}  // namespace railmodal::study
