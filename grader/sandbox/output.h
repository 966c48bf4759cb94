// A sandboxed program's captured output (stdout and stderr on one pipe): what the grader keeps of
// it, and how it reads the pipe. Takes the pipe's read end (non-blocking); gives the text, cut at
// a cap.
#pragma once

#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

namespace a6::grader::sandboxing {

// What was read, up to `cap` bytes; the rest is counted as truncated. add() and text() may be
// called from two threads (the drainer and its owner); `truncated` is read once reading is over.
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

// Reads what the pipe holds now, at most kReadsPerCall chunks; false at end of stream or on a
// hard error.
bool readSome(int fd, Sink& sink);

// After the program ended: reads everything its processes left in the pipe, and waits for the
// pipe's end (a process that escaped could hold it open forever) until `graceEnd`. What is
// already in the pipe (64 KiB by default) is read even when `graceEnd` has passed: a grader
// held up by the load does not lose what the program wrote.
void readAfterEnd(int fd, Sink& sink, std::chrono::steady_clock::time_point graceEnd);

}  // namespace a6::grader::sandboxing
