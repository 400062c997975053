#include "tetcut/harness/child_process.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>

namespace tetcut::harness {

namespace {

// Messages on the pipe: one per line, the first character says what it is.
constexpr char kAnnounce = 'A';
constexpr char kPayload = 'P';
constexpr char kThrown = 'E';

void write_all(int fd, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // the parent is gone: nothing to tell
    done += static_cast<std::size_t>(n);
  }
}

void send(int fd, char kind, std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  write_all(fd, kind + text + '\n');
}

}  // namespace

std::string ChildOutcome::failure() const {
  if (completed) return "";
  std::string what;
  if (!error.empty()) {
    what = error;
  } else if (signal != 0) {
    const char* name = strsignal(signal);
    what = "killed by signal " + std::to_string(signal) + " (" + (name != nullptr ? name : "unknown") + ")";
  } else {
    what = "exited with code " + std::to_string(exit_code) + " without a result";
  }
  if (!last_announced.empty()) what += " during " + last_announced;
  return what;
}

ChildOutcome run_in_child(const std::function<std::string(const Announce&)>& work, unsigned timeout_seconds) {
  ChildOutcome outcome;
  int fds[2];
  if (pipe(fds) != 0) {
    outcome.error = std::string("pipe: ") + std::strerror(errno);
    return outcome;
  }
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) {
    outcome.error = std::string("fork: ") + std::strerror(errno);
    close(fds[0]);
    close(fds[1]);
    return outcome;
  }
  if (pid == 0) {
    close(fds[0]);
    const int out = fds[1];
    if (timeout_seconds > 0) alarm(timeout_seconds);
    int code = 0;
    try {
      const std::string payload = work([out](const std::string& line) { send(out, kAnnounce, line); });
      send(out, kPayload, payload);
    } catch (const std::exception& e) {
      send(out, kThrown, e.what());
      code = 1;
    } catch (...) {
      send(out, kThrown, "an exception that is not a std::exception");
      code = 1;
    }
    close(out);
    std::fflush(nullptr);
    _exit(code);  // no destructors or atexit handlers of the parent's state run twice
  }
  close(fds[1]);
  std::string received;
  char buffer[65536];
  for (;;) {
    const ssize_t n = read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    received.append(buffer, static_cast<std::size_t>(n));
  }
  close(fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  bool have_payload = false;
  std::size_t start = 0;
  while (start < received.size()) {
    std::size_t end = received.find('\n', start);
    if (end == std::string::npos) break;  // a line cut short by the child's death
    const char kind = received[start];
    std::string text = received.substr(start + 1, end - start - 1);
    if (kind == kAnnounce) outcome.last_announced = std::move(text);
    if (kind == kPayload) {
      outcome.payload = std::move(text);
      have_payload = true;
    }
    if (kind == kThrown) outcome.error = std::move(text);
    start = end + 1;
  }
  if (WIFSIGNALED(status)) {
    outcome.signal = WTERMSIG(status);
  } else if (WIFEXITED(status)) {
    outcome.exit_code = WEXITSTATUS(status);
    outcome.completed = have_payload && outcome.exit_code == 0;
  }
  return outcome;
}

}  // namespace tetcut::harness
