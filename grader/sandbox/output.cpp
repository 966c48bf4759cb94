// A sandboxed program's captured output (see output.h).
#include "sandbox/output.h"

#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>

namespace a6::grader::sandboxing {

void Sink::add(const char* bytes, std::size_t n) {
  std::lock_guard<std::mutex> lock(mutex);
  const std::size_t room = cap > data.size() ? cap - data.size() : 0;
  data.append(bytes, std::min(room, n));
  if (n > room) truncated = true;
}

std::string Sink::text() const {
  std::lock_guard<std::mutex> lock(mutex);
  return data;
}

bool readSome(int fd, Sink& sink) {
  char buffer[kReadChunk];
  for (std::size_t reads = 0; reads < kReadsPerCall; ++reads) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n > 0) {
      sink.add(buffer, static_cast<std::size_t>(n));
      continue;
    }
    if (n == 0) return false;
    if (errno == EINTR) continue;
    return errno == EAGAIN || errno == EWOULDBLOCK;
  }
  return true;
}

void readAfterEnd(int fd, Sink& sink, std::chrono::steady_clock::time_point graceEnd) {
  using Clock = std::chrono::steady_clock;
  while (readSome(fd, sink)) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(graceEnd - Clock::now());
    if (left.count() <= 0) return;
    pollfd pfd{fd, POLLIN, 0};
    poll(&pfd, 1, static_cast<int>(std::min<long long>(left.count() + 1, 1000)));
  }
}

}  // namespace a6::grader::sandboxing
