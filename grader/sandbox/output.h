// A sandboxed program's captured output (stdout and stderr on one non-blocking pipe), cut at a
// cap.
#pragma once

#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

namespace a6::grader::sandboxing {

// What was read, up to `cap` bytes. add() and text() may be called from two threads (the
// drainer and its owner); `truncated` is read once reading is over.
struct Sink {
  mutable std::mutex mutex;
  std::string data;
  std::size_t cap = 0;
  bool truncated = false;

  void add(const char* bytes, std::size_t n);
  std::string text() const;
};

// What one readSome() reads at most: a writer that never stops cannot keep the reader there.
inline constexpr std::size_t kReadChunk = 64 << 10, kReadsPerCall = 64;  // 4 MiB

// Reads what the pipe holds now (at most kReadsPerCall chunks); false at its end or an error.
bool readSome(int fd, Sink& sink);

// After the program ended: reads the pipe until its end or `graceEnd` (an escaped process
// could hold it open forever). What is already in it is read even after `graceEnd`, so that a
// grader held up by the load loses nothing the program wrote.
void readAfterEnd(int fd, Sink& sink, std::chrono::steady_clock::time_point graceEnd);

}  // namespace a6::grader::sandboxing
