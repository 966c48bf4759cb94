// a6-keeper: the init of a sandboxed command's pid namespace (grader/sandbox/sandbox.h), run in
// place of the grader's copy that set the namespace up, so that the copy's memory (the whole
// grader's, shared copy-on-write) is not held while the program runs.
//
//   a6-keeper END_FD
// Takes: the program, its child with pid 2 in this namespace (the first the set-up forked), and
// END_FD, a pipe to the grader. Gives: the program's wait status on END_FD once it ends, then
// exits, which ends every process left in the namespace. Reaps every orphan meanwhile.
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
