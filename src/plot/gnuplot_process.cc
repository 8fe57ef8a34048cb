#include "plot/gnuplot_process.h"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <stdexcept>

extern char** environ;

namespace musclesim {

namespace {

constexpr std::size_t kMessageLimit = 16384;  // [bytes] of gnuplot's messages kept

std::runtime_error StartFailure(int error) {
  return std::runtime_error(std::string("cannot start gnuplot (") + std::strerror(error) + ")");
}

// Writes the script into `in` and reads what gnuplot prints from `out` at the same time, so
// that neither side waits on a full pipe; gnuplot stopping early (an error in the script)
// ends the writing without SIGPIPE, as `in` is a socket written with MSG_NOSIGNAL.
void Exchange(int in, int out, const std::string& script, std::string& messages) {
  std::size_t written = 0;
  if (script.empty()) ::shutdown(in, SHUT_WR);
  bool writing = !script.empty();
  char buffer[4096];
  for (;;) {
    pollfd fds[2] = {{out, POLLIN, 0}, {in, POLLOUT, 0}};
    if (::poll(fds, writing ? 2 : 1, -1) < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(std::string("gnuplot: poll failed (") + std::strerror(errno) + ")");
    }
    if (writing && (fds[1].revents & (POLLOUT | POLLERR | POLLHUP)) != 0) {
      const ssize_t n =
          ::send(in, script.data() + written, script.size() - written, MSG_NOSIGNAL | MSG_DONTWAIT);
      if (n > 0) written += static_cast<std::size_t>(n);
      const bool failed = n < 0 && errno != EINTR && errno != EAGAIN && errno != EWOULDBLOCK;
      if (failed || written == script.size()) {
        ::shutdown(in, SHUT_WR);  // end of the script: gnuplot reads end of file
        writing = false;
      }
    }
    if ((fds[0].revents & (POLLIN | POLLHUP | POLLERR)) != 0) {
      const ssize_t n = ::read(out, buffer, sizeof buffer);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return;  // gnuplot closed its output: it has ended
      // the first messages say what went wrong; what follows them is kept out of memory
      if (messages.size() < kMessageLimit) {
        messages.append(buffer,
                        std::min(static_cast<std::size_t>(n), kMessageLimit - messages.size()));
      }
    }
  }
}

}  // namespace

bool RunGnuplot(const std::string& script, std::string& messages) {
  int in[2];
  int out[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, in) != 0) throw StartFailure(errno);
  if (::pipe2(out, O_CLOEXEC) != 0) {
    const int error = errno;
    ::close(in[0]);
    ::close(in[1]);
    throw StartFailure(error);
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, in[1], 0);
  // gnuplot reading a script from its standard input goes on after an error: a `set output`
  // it could not open leaves the plot to go to standard output, so that goes nowhere; its
  // messages (errors, warnings, print) are on standard error
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, out[1], 2);
  std::string program = "gnuplot";
  char* argv[] = {program.data(), nullptr};
  pid_t pid = 0;
  const int spawned = ::posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(in[1]);
  ::close(out[1]);
  if (spawned != 0) {
    ::close(in[0]);
    ::close(out[0]);
    if (spawned == ENOENT) {
      throw std::runtime_error(
          "gnuplot is not installed (or not on PATH): install the Debian package gnuplot-nox "
          "(scripts/install-deps.sh does)");
    }
    throw StartFailure(spawned);
  }
  try {
    Exchange(in[0], out[0], script, messages);
  } catch (...) {
    ::close(in[0]);
    ::close(out[0]);
    ::kill(pid, SIGKILL);
    while (::waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {}
    throw;
  }
  ::close(in[0]);
  ::close(out[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace musclesim
