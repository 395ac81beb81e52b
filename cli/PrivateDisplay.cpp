#include "PrivateDisplay.h"

#include "MedialXDisplay.h"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

namespace medial::cli {
namespace {

std::string findInPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  size_t start = 0;
  while (start <= dirs.size()) {
    const size_t end = dirs.find(':', start);
    const std::string dir = dirs.substr(start, end == std::string::npos ? std::string::npos : end - start);
    const std::string candidate = (dir.empty() ? "." : dir) + "/" + program;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return {};
}

}  // namespace

PrivateDisplay::~PrivateDisplay() {
  medial::closeXDisplay(display_);
  if (xvfb_ > 0) {
    ::kill(xvfb_, SIGTERM);
    ::waitpid(xvfb_, nullptr, 0);
  }
}

bool PrivateDisplay::ensure(std::string& error) {
  if ((display_ = medial::openXDisplay())) return true;
  const std::string xvfb = findInPath("Xvfb");
  if (xvfb.empty()) {
    error =
        "no X display to render with (DISPLAY is unset or unreachable) and Xvfb is not installed: "
        "run 'apt-get install xvfb xauth' or start medial under xvfb-run";
    return false;
  }
  int fds[2];
  if (::pipe(fds) != 0) {
    error = std::string("cannot start Xvfb: ") + std::strerror(errno);
    return false;
  }
  const pid_t pid = ::fork();
  if (pid < 0) {
    error = std::string("cannot start Xvfb: ") + std::strerror(errno);
    return false;
  }
  if (pid == 0) {  // child: Xvfb writes its display number to fds[1] once it accepts connections
    ::close(fds[0]);
    const int devnull = ::open("/dev/null", O_RDWR);
    ::dup2(devnull, STDIN_FILENO);
    ::dup2(devnull, STDOUT_FILENO);
    ::dup2(devnull, STDERR_FILENO);
    const std::string fd = std::to_string(fds[1]);
    ::execl(xvfb.c_str(), "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1920x1200x24", "-nolisten",
            "tcp", "+extension", "GLX", "-nocursor", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(fds[1]);
  xvfb_ = pid;
  std::string number;
  pollfd waitFor{fds[0], POLLIN, 0};
  char buffer[32];
  while (number.find('\n') == std::string::npos && ::poll(&waitFor, 1, 15000) > 0) {
    const ssize_t got = ::read(fds[0], buffer, sizeof buffer);
    if (got <= 0) break;
    number.append(buffer, static_cast<size_t>(got));
  }
  ::close(fds[0]);
  while (!number.empty() && (number.back() == '\n' || number.back() == ' ')) number.pop_back();
  if (number.empty()) {
    error = "no X display to render with, and the private Xvfb did not start (" + xvfb + ")";
    return false;
  }
  ::setenv("DISPLAY", (":" + number).c_str(), 1);
  if (!(display_ = medial::openXDisplay())) {
    error = "the private Xvfb on :" + number + " does not accept connections";
    return false;
  }
  return true;
}

}  // namespace medial::cli
