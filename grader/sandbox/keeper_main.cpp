// a6-keeper END_FD: the init of a sandboxed command's pid namespace (sandbox.h), exec'd in place
// of the grader's copy that set it up, so that the grader's memory is not held while the program
// runs. Reaps every orphan; when the program (pid 2) ends, writes its wait status on END_FD and
// exits, which ends every process left in the namespace.
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>

int main(int argc, char** argv) {
  if (argc != 2) return 126;
  const int endFd = std::atoi(argv[1]);
  constexpr pid_t kProgram = 2;
  for (;;) {
    int status = 0;
    const pid_t got = waitpid(-1, &status, __WALL);
    if (got == kProgram) {
      const ssize_t written = write(endFd, &status, sizeof status);
      _exit(written == static_cast<ssize_t>(sizeof status) ? 0 : 125);
    }
    if (got < 0 && errno != EINTR) _exit(126);
  }
}
