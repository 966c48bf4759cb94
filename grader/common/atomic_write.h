// A file written whole or not at all: a temporary file beside it, written, synced, then renamed
// over it. results.json, report.html, the batch's markers and gradebook, the insights page.
#pragma once

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>

namespace a6::grader {

/// Writes `text` to `file` atomically (its folder created); returns an empty string or the error.
inline std::string writeFileAtomically(const std::filesystem::path& file, const std::string& text) {
  std::error_code ec;
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ec);
  if (ec) return "cannot create " + file.parent_path().string() + ": " + ec.message();
  const std::filesystem::path tmp =
      file.string() + ".tmp." + std::to_string(static_cast<long>(::getpid()));
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return "cannot write " + tmp.string() + ": " + std::strerror(errno);
  // A failure's words (errno read first), the temporary file removed.
  auto failed = [&](const std::string& what) {
    const std::string why = std::strerror(errno);
    ::unlink(tmp.c_str());
    return what + ": " + why;
  };
  for (std::size_t done = 0; done < text.size();) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string why = failed("cannot write " + tmp.string());
      ::close(fd);
      return why;
    }
    done += static_cast<std::size_t>(n);
  }
  const bool synced = ::fsync(fd) == 0;  // closed either way
  if (::close(fd) != 0 || !synced) return failed("cannot write " + tmp.string());
  if (::rename(tmp.c_str(), file.c_str()) != 0) {
    return failed("cannot rename " + tmp.string() + " to " + file.string());
  }
  return {};
}

}  // namespace a6::grader
